#include "app/obstacle_drag.h"

#include <cmath>

#include "core/obstacles/obstacle_pick.h"
#include "core/sim/attribute_table.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

constexpr float kPrimitiveGrab = 0.25f;  // m: how near a primitive's centre a press grabs it

// The nearest hit of the ray on a ball of kPrimitiveGrab about each active primitive.
std::optional<std::pair<int, glm::vec3>> pickPrimitive(const ParticleState& state,
                                                       const WorldRay& ray) {
  std::optional<std::pair<int, glm::vec3>> best;
  float bestT = INFINITY;
  const glm::vec3 d = glm::normalize(ray.direction);
  for (std::size_t i = 0; i < state.primitives.size(); ++i) {
    if (!state.primitives[i].active()) continue;
    const glm::vec3 m = ray.origin - state.primitives[i].position;
    const float b = glm::dot(m, d), c = glm::dot(m, m) - kPrimitiveGrab * kPrimitiveGrab;
    const float disc = b * b - c;
    if (disc < 0.0f) continue;
    const float t = -b - std::sqrt(disc);
    if (t >= 0.0f && t < bestT) {
      bestT = t;
      best = {{int(i), ray.origin + t * d}};
    }
  }
  return best;
}

}  // namespace

bool ObstacleDrag::pick(const ParticleState& state, const WorldRay& ray) {
  const std::optional<ObstacleHit> obstacle =
      pickObstacle(state.obstacles, ray.origin, ray.direction);
  const auto primitive = pickPrimitive(state, ray);
  const float toObstacle = obstacle ? glm::distance(ray.origin, obstacle->point) : INFINITY;
  if (primitive && glm::distance(ray.origin, primitive->second) < toObstacle) {
    held_ = Held{concat("primitive.", primitive->first, "."), false};
    grabHeight_ = primitive->second.z;
    offset_ = state.primitives[std::size_t(primitive->first)].position - primitive->second;
    log::info("primitive ", primitive->first, " grabbed: drag it along the floor");
    return true;
  }
  if (!obstacle) return false;
  held_ = Held{concat("obstacle.", obstacle->index, "."), true};
  grabHeight_ = obstacle->point.z;
  offset_ = state.obstacles[std::size_t(obstacle->index)].position - obstacle->point;
  log::info("obstacle ", obstacle->index, " grabbed: drag it along the floor");
  return true;
}

void ObstacleDrag::drag(MainContext& main, const WorldRay& ray, float dt, bool released) {
  if (!held_) return;
  const std::string& key = held_->prefix;
  try {
    const ParticleState state = main.pendingState();
    const glm::vec3 from =
        std::get<glm::vec3>(AttributeTable::instance().get(state, key + "position"));
    glm::vec3 to = from;
    if (const std::optional<glm::vec3> p = dragOnFloor(ray.origin, ray.direction, grabHeight_)) {
      to = *p + offset_;
      to.z = from.z;  // along the floor
    }
    if (held_->obstacle && std::get<bool>(AttributeTable::instance().get(state, key + "path")))
      main.set(key + "path", false);
    if (to != from) main.set(key + "position", to);
    if (held_->obstacle) {
      const glm::vec3 velocity = released || !(dt > 0.0f) ? glm::vec3(0.0f) : (to - from) / dt;
      main.set(key + "velocity", velocity);
    }
  } catch (const Error& e) {
    log::warn(key, ": ", e.what());  // e.g. the obstacle is gone
    held_.reset();
    return;
  }
  if (released) held_.reset();
}

}  // namespace sandstorm
