#include "app/molecule_push.h"

#include <algorithm>

#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {

glm::vec3 MoleculePush::pushPoint(const WorldRay& ray, const glm::vec3& centre) {
  const glm::vec3 d = glm::normalize(ray.direction);
  return ray.origin + d * std::max(glm::dot(centre - ray.origin, d), 0.0f);
}

bool MoleculePush::press(MainContext& main, const WorldRay& ray, const glm::vec3& centre) {
  if (!main.pendingState().molecules.pushTool) return false;
  try {
    main.set("molecules.push_position", pushPoint(ray, centre));
    main.set("molecules.push", true);
    holding_ = true;
  } catch (const Error& e) {
    log::warn("push: ", e.what());
  }
  return holding_;
}

void MoleculePush::drag(MainContext& main, const WorldRay& ray, const glm::vec3& centre,
                        bool released) {
  if (!holding_) return;
  try {
    if (released) {
      main.set("molecules.push", false);
      holding_ = false;
      return;
    }
    const glm::vec3 at = pushPoint(ray, centre);
    if (at != main.pendingState().molecules.pushPosition) main.set("molecules.push_position", at);
  } catch (const Error& e) {
    log::warn("push: ", e.what());
    holding_ = false;
  }
}

}  // namespace sandstorm
