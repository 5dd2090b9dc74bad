#include "core/obstacles/obstacle_pick.h"

#include <cmath>

#include "core/obstacles/obstacle_physics.h"

namespace sandstorm {
namespace {

constexpr int kMaxSteps = 128;
constexpr float kHitDistance = 1e-3f;

std::optional<float> traceTo(const Obstacle& o, const glm::vec3& origin, const glm::vec3& direction,
                             float reach) {
  float t = 0.0f;
  for (int i = 0; i < kMaxSteps && t <= reach; ++i) {
    const float d = obstacleSurface(o, origin + t * direction).distance;
    if (d < kHitDistance) return t;
    t += d;
  }
  return std::nullopt;
}

}  // namespace

std::optional<ObstacleHit> pickObstacle(std::span<const Obstacle> obstacles,
                                        const glm::vec3& origin, const glm::vec3& direction,
                                        float reach) {
  std::optional<ObstacleHit> best;
  float bestT = reach;
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    if (!obstacles[i].enabled) continue;
    const std::optional<float> t = traceTo(obstacles[i], origin, direction, bestT);
    if (t && (!best || *t < bestT)) {
      bestT = *t;
      best = ObstacleHit{int(i), origin + *t * direction};
    }
  }
  return best;
}

std::optional<glm::vec3> dragOnFloor(const glm::vec3& origin, const glm::vec3& direction,
                                     float grabHeight, float reach) {
  if (std::abs(direction.z) < 1e-6f) return std::nullopt;
  const float t = (grabHeight - origin.z) / direction.z;
  if (!(t > 0.0f && t <= reach)) return std::nullopt;
  return origin + t * direction;
}

}  // namespace sandstorm
