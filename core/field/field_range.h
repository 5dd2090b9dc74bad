// FieldRange: the range of a field's speed, of each velocity component (turned
// by the placement's rotation into the particles' axes) and of its vorticity
// magnitude over its valid grid points: the ends of a colour scale that
// follows the field (ColorRange::Field), as ParaView's "data range". In the
// field's own units: the particles feel strength * scale times the velocity
// and strength times the vorticity (resolveColorScale applies both). Computed
// once per field frame by the main context and carried with it to every wall.
#pragma once

#include <glm/glm.hpp>

#include "core/field/vector_field.h"

namespace sandstorm {

struct FieldRange {
  float minSpeed = 0.0f;
  float maxSpeed = 1.0f;
  glm::vec3 minVelocity{-1.0f};
  glm::vec3 maxVelocity{1.0f};
  float minVorticity = 0.0f;
  float maxVorticity = 1.0f;

  // Over the valid points; an empty field (or one with no valid point) gives
  // the defaults. `vorticity`: vorticityMagnitude(field), or null (range 0..1).
  static FieldRange of(const VectorField& field, const glm::mat3& rotation = glm::mat3(1.0f),
                       const VectorField* vorticity = nullptr);
  bool operator==(const FieldRange&) const = default;
};

}  // namespace sandstorm
