// FieldRange: the range of a field's speed, of each velocity component (turned
// by the placement's rotation into the particles' axes) and of its colour
// grid (vorticity magnitude or a scalar array) over its valid grid points: the ends of a colour
// scale that follows the field (ColorRange::Field), as ParaView's "data range". In the field's own
// units: the particles feel strength * scale times the velocity and strength times the vorticity
// (resolveColorScale applies both). Computed once per field frame by the main context and carried
// with it to every wall.
#pragma once

#include <glm/glm.hpp>

#include "core/field/sparse_field.h"
#include "core/field/vector_field.h"

namespace sandstorm {

struct FieldRange {
  float minSpeed = 0.0f;
  float maxSpeed = 1.0f;
  glm::vec3 minVelocity{-1.0f};
  glm::vec3 maxVelocity{1.0f};
  float minScalar = 0.0f;  // the colour grid's range
  float maxScalar = 1.0f;

  // Over the valid points (and the colour grid's finite values); an empty
  // field (or one with no valid point) gives the defaults. `colorGrid`: the
  // quantity in x on the field's points (core/color/color_grid.h), or null
  // (range 0..1).
  static FieldRange of(const VectorField& field, const glm::mat3& rotation = glm::mat3(1.0f),
                       const VectorField* colorGrid = nullptr);
  // Over a sparse grid's active values (voxels and tiles).
  static FieldRange of(const SparseField& field, const glm::mat3& rotation = glm::mat3(1.0f));
  bool operator==(const FieldRange&) const = default;
};

}  // namespace sandstorm
