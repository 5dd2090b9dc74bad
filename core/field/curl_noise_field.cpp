#include "core/field/curl_noise_field.h"

#include "core/util/error.h"

namespace sandstorm {

CurlNoiseField::CurlNoiseField(const CurlNoiseParams& params)
    : params_(params),
      n1_(params.seed * 3u + 0u),
      n2_(params.seed * 3u + 1u),
      n3_(params.seed * 3u + 2u) {
  if (!(params.scale > 0.0f))
    throw Error(concat("CurlNoiseField: scale is ", params.scale, "; expected > 0"));
}

glm::vec3 CurlNoiseField::evaluate(const glm::vec3& p) const {
  const glm::vec3 q = (p + params_.offset) / params_.scale;
  // Gradients with respect to q; d/dp = (1 / scale) d/dq, cancelled by `amplitude * scale`.
  const glm::vec3 g1(n1_.valueAndGradient(q));
  const glm::vec3 g2(n2_.valueAndGradient(q));
  const glm::vec3 g3(n3_.valueAndGradient(q));
  const glm::vec3 curl(g3.y - g2.z, g1.z - g3.x, g2.x - g1.y);
  return params_.amplitude * curl;
}

}  // namespace sandstorm
