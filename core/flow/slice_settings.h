// SliceSettings: the slice plane through the field (the attributes slice.*),
// coloured by the field's render.color_by quantity through render.color_map.
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

struct SliceSettings {
  bool enabled = false;
  glm::vec3 origin{0.0f, 0.0f, 2.0f};  // a point of the plane (the particles' coordinates)
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // its normal (any length but 0)
  float opacity = 1.0f;
};

}  // namespace sandstorm
