#include "core/field/wind_field.h"

#include <cmath>

#include "core/util/error.h"

namespace sandstorm {

WindField::WindField(const WindParams& params)
    : params_(params),
      nx_(params.seed * 3u + 0u),
      ny_(params.seed * 3u + 1u),
      nz_(params.seed * 3u + 2u) {
  if (!(glm::length(params.direction) > 0.0f)) throw Error("WindField: direction must not be zero");
  if (!(params.noise >= 0.0f))
    throw Error(concat("WindField: noise is ", params.noise, "; expected >= 0"));
  if (!(params.noiseScale > 0.0f))
    throw Error(concat("WindField: noise scale is ", params.noiseScale, "; expected > 0"));
  direction_ = glm::normalize(params.direction);
}

glm::vec3 WindField::evaluate(const glm::vec3& p) const {
  glm::vec3 v = params_.power * direction_;
  if (params_.noise > 0.0f) {
    const glm::vec3 q = p / params_.noiseScale;
    v += params_.noise * glm::vec3(nx_.value(q), ny_.value(q), nz_.value(q));
  }
  return v;
}

}  // namespace sandstorm
