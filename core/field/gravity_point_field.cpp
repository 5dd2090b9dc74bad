#include "core/field/gravity_point_field.h"

#include <algorithm>
#include <cmath>

#include "core/util/error.h"

namespace sandstorm {

GravityPointField::GravityPointField(const GravityPointParams& params) : params_(params) {
  if (!(params.range > 0.0f) || !std::isfinite(params.range))
    throw Error(concat("GravityPointField: range is ", params.range, "; expected > 0"));
}

glm::vec3 GravityPointField::evaluate(const glm::vec3& p) const {
  const glm::vec3 d = params_.center - p;
  const float distance = glm::length(d);
  if (distance <= 0.0f) return glm::vec3(0.0f);
  const float percent = std::clamp((params_.range - distance) / params_.range, 0.0f, 1.0f);
  return d * (params_.power * percent / distance);
}

}  // namespace sandstorm
