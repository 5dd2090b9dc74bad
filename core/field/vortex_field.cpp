#include "core/field/vortex_field.h"

#include <algorithm>

#include "core/util/error.h"

namespace sandstorm {

VortexField::VortexField(const VortexParams& params) : params_(params) {
  if (glm::length(params.axis) <= 0.0f) throw Error("VortexField: axis must not be zero");
  if (!(params.range > 0.0f) || !(params.height > 0.0f) || params.core < 0.0f)
    throw Error("VortexField: range and height must be > 0 and core >= 0");
  axis_ = glm::normalize(params.axis);
}

glm::vec3 VortexField::evaluate(const glm::vec3& p) const {
  const glm::vec3 t = p - params_.center;
  const float along = glm::dot(t, axis_);
  if (along < 0.0f || along > params_.height) return glm::vec3(0.0f);

  const glm::vec3 radial = t - along * axis_;
  const float rho = glm::length(radial);
  const float falloff = std::clamp((params_.range - rho) / params_.range, 0.0f, 1.0f);
  if (falloff <= 0.0f) return glm::vec3(0.0f);

  // radial / max(rho, core): unit length outside the core, shrinking to zero on the axis.
  const float scale = std::max(rho, params_.core);
  const glm::vec3 outward = scale > 0.0f ? radial / scale : glm::vec3(0.0f);
  const glm::vec3 around = glm::cross(axis_, outward);
  return falloff * (params_.spin * around - params_.pull * outward + params_.up * axis_);
}

}  // namespace sandstorm
