// AnalyticField: a vector field given by an equation, evaluated anywhere.
// Analytic fields are baked into a VectorField grid (bake()) before upload.
#pragma once

#include <glm/glm.hpp>

#include "core/field/vector_field.h"

namespace sandstorm {

class AnalyticField {
 public:
  virtual ~AnalyticField() = default;
  virtual glm::vec3 evaluate(const glm::vec3& p) const = 0;
};

// Samples `field` at every grid point of a bounds x dims grid.
VectorField bake(const AnalyticField& field, const Box& bounds, const glm::ivec3& dims);

}  // namespace sandstorm
