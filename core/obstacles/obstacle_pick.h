// Picking and dragging obstacles with a pointer (the desktop's mouse; the
// tracked wand grabs them as it grabs emitters, wand_handles.h): where a ray
// first meets an obstacle, and where a drag along the floor puts it.
#pragma once

#include <optional>
#include <span>

#include <glm/glm.hpp>

#include "core/obstacles/obstacle.h"

namespace sandstorm {

struct ObstacleHit {
  int index = 0;          // into the list given
  glm::vec3 point{0.0f};  // where the ray meets its surface
};

// The nearest enabled obstacle the ray (origin, unit direction) meets within
// `reach` metres, found by sphere tracing its signed distance.
std::optional<ObstacleHit> pickObstacle(std::span<const Obstacle> obstacles,
                                        const glm::vec3& origin, const glm::vec3& direction,
                                        float reach = 1000.0f);

// Dragging along the floor: the grabbed point slides in its horizontal plane
// (z = grabHeight), following the ray; none when the ray runs parallel to the
// plane or meets it behind the origin or beyond `reach`.
std::optional<glm::vec3> dragOnFloor(const glm::vec3& origin, const glm::vec3& direction,
                                     float grabHeight, float reach = 1000.0f);

}  // namespace sandstorm
