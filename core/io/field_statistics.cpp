#include "core/io/field_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sandstorm {

FieldStatistics computeStatistics(const VectorField& field) {
  FieldStatistics s;
  float lo = std::numeric_limits<float>::infinity(), hi = 0.0f;
  double sum = 0.0;
  std::size_t finite = 0;
  for (const glm::vec3& v : field.values()) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      ++s.nonFinite;
      continue;
    }
    const float m = glm::length(v);
    lo = std::min(lo, m);
    hi = std::max(hi, m);
    sum += m;
    ++finite;
    if (v == glm::vec3(0.0f)) ++s.zero;
  }
  if (finite > 0) {
    s.minMagnitude = lo;
    s.maxMagnitude = hi;
    s.meanMagnitude = sum / double(finite);
  }
  return s;
}

}  // namespace sandstorm
