// FieldRange: the range of a field's speed and of each velocity component
// over its valid grid points: the ends of a colour scale that follows the
// field (ColorRange::Field), as ParaView's "data range". Computed once per
// field frame by the main context and carried with it to every wall.
#pragma once

#include <glm/glm.hpp>

#include "core/field/vector_field.h"

namespace sandstorm {

struct FieldRange {
  float minSpeed = 0.0f;
  float maxSpeed = 1.0f;
  glm::vec3 minVelocity{-1.0f};
  glm::vec3 maxVelocity{1.0f};

  // Over the valid points; an empty field (or one with no valid point) gives the defaults.
  static FieldRange of(const VectorField& field);
  bool operator==(const FieldRange&) const = default;
};

}  // namespace sandstorm
