#include "app/obstacle_drag.h"

#include "core/obstacles/obstacle_pick.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {

bool ObstacleDrag::pick(const ParticleState& state, const WorldRay& ray) {
  const std::optional<ObstacleHit> hit = pickObstacle(state.obstacles, ray.origin, ray.direction);
  if (!hit) return false;
  index_ = hit->index;
  grabHeight_ = hit->point.z;
  offset_ = state.obstacles[std::size_t(hit->index)].position - hit->point;
  log::info("obstacle ", hit->index, " grabbed: drag it along the floor");
  return true;
}

void ObstacleDrag::drag(MainContext& main, const WorldRay& ray, float dt, bool released) {
  if (!index_) return;
  const std::string key = concat("obstacle.", *index_, ".");
  const ParticleState state = main.pendingState();
  if (std::size_t(*index_) >= state.obstacles.size()) {
    index_.reset();
    return;
  }
  const glm::vec3 from = state.obstacles[std::size_t(*index_)].position;
  glm::vec3 to = from;
  if (const std::optional<glm::vec3> p = dragOnFloor(ray.origin, ray.direction, grabHeight_)) {
    to = *p + offset_;
    to.z = from.z;  // along the floor
  }
  try {
    if (state.obstacles[std::size_t(*index_)].path) main.set(key + "path", false);
    if (to != from) main.set(key + "position", to);
    const glm::vec3 velocity = released || !(dt > 0.0f) ? glm::vec3(0.0f) : (to - from) / dt;
    main.set(key + "velocity", velocity);
  } catch (const Error& e) {
    log::warn("obstacle ", *index_, ": ", e.what());
  }
  if (released) index_.reset();
}

}  // namespace sandstorm
