// WindField: the wind of the texture-vs-equation thesis (appendix B),
//   v = power * d^ + noise * r(p)
// where d^ is the unit wind direction and r a smooth random vector field with
// components in about [-1, 1]: three gradient-noise channels of feature size
// `noiseScale` metres. The thesis hashes each texel independently; a smooth r
// keeps the field well sampled at any grid resolution.
#pragma once

#include <cstdint>

#include "core/field/analytic_field.h"
#include "core/field/gradient_noise.h"

namespace sandstorm {

struct WindParams {
  glm::vec3 direction{1.0f, 0.0f, 0.0f};  // not zero
  float power = 3.0f;                     // m/s along the direction; negative blows backwards
  float noise = 0.5f;                     // m/s: amplitude of the random part, >= 0
  float noiseScale = 2.0f;                // m: feature size of the random part, > 0
  std::uint32_t seed = 1;
};

class WindField final : public AnalyticField {
 public:
  explicit WindField(const WindParams& params);
  glm::vec3 evaluate(const glm::vec3& p) const override;
  const WindParams& params() const { return params_; }

 private:
  WindParams params_;
  glm::vec3 direction_;
  GradientNoise nx_, ny_, nz_;
};

}  // namespace sandstorm
