#include "core/field/field_range.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sandstorm {

FieldRange FieldRange::of(const VectorField& field, const glm::mat3& rotation,
                          const VectorField* colorGrid) {
  const auto values = field.values();
  const auto valid = field.validity();
  FieldRange r;
  r.minSpeed = std::numeric_limits<float>::max();
  r.maxSpeed = 0.0f;
  r.minVelocity = glm::vec3(std::numeric_limits<float>::max());
  r.maxVelocity = glm::vec3(std::numeric_limits<float>::lowest());
  bool any = false;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!valid.empty() && valid[i] == 0) continue;
    const glm::vec3 v = rotation * values[i];
    const float speed = glm::length(v);
    r.minSpeed = std::min(r.minSpeed, speed);
    r.maxSpeed = std::max(r.maxSpeed, speed);
    r.minVelocity = glm::min(r.minVelocity, v);
    r.maxVelocity = glm::max(r.maxVelocity, v);
    any = true;
  }
  if (!any) return FieldRange{};
  if (colorGrid && colorGrid->pointCount() == values.size()) {
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    const auto w = colorGrid->values();
    for (std::size_t i = 0; i < w.size(); ++i) {
      if ((!valid.empty() && valid[i] == 0) || !std::isfinite(w[i].x)) continue;
      lo = std::min(lo, w[i].x);
      hi = std::max(hi, w[i].x);
    }
    if (lo <= hi) {
      r.minScalar = lo;
      r.maxScalar = hi;
    }
  }
  return r;
}

}  // namespace sandstorm
