// FieldStatistics: a summary of a VectorField's values for `sandstorm-field
// info` and logs: vector length minimum, maximum and mean, and the count of
// non-finite vectors still present (loaders replace them by zero, so a loaded
// field has none; LoadReport::nonFinite counts those replaced).
#pragma once

#include <cstddef>

#include "core/field/vector_field.h"

namespace sandstorm {

struct FieldStatistics {
  float minMagnitude = 0.0f;
  float maxMagnitude = 0.0f;
  double meanMagnitude = 0.0;
  std::size_t nonFinite = 0;
  std::size_t zero = 0;  // exactly zero vectors
};

FieldStatistics computeStatistics(const VectorField& field);

}  // namespace sandstorm
