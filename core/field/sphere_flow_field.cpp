#include "core/field/sphere_flow_field.h"

#include <cmath>
#include <numbers>

#include "core/util/error.h"

namespace sandstorm {

SphereFlowField::SphereFlowField(const SphereFlowParams& params) : params_(params) {
  if (!(params.radius > 0.0f))
    throw Error(concat("SphereFlowField: radius is ", params.radius, "; expected > 0"));
  if (!(glm::length(params.direction) > 0.0f))
    throw Error("SphereFlowField: direction must not be zero");
  if (!(params.epsilon >= 0.0f))
    throw Error(concat("SphereFlowField: epsilon is ", params.epsilon, "; expected >= 0"));
  stream_ = params.speed * glm::normalize(params.direction);
}

glm::vec3 SphereFlowField::evaluate(const glm::vec3& p) const {
  const glm::vec3 x = p - params_.center;
  const float r2 = glm::dot(x, x);
  const float R = params_.radius;
  if (r2 < R * R) return glm::vec3(0.0f);
  const float r = std::sqrt(r2);
  const float r3 = r2 * r, r5 = r3 * r2;
  const float halfR3 = 0.5f * R * R * R;
  glm::vec3 v = stream_ + halfR3 * (stream_ / r3 - (3.0f * glm::dot(stream_, x) / r5) * x);
  if (params_.source != 0.0f) {
    const float e2 = params_.epsilon * params_.epsilon;
    const float d = std::pow(r2 + e2, 1.5f);
    v += (params_.source / (4.0f * std::numbers::pi_v<float>)) * x / d;
  }
  return v;
}

}  // namespace sandstorm
