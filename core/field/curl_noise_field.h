// CurlNoiseField: a divergence-free turbulent velocity field (Bridson et al.,
// "Curl-Noise for Procedural Fluid Flow", 2007; the Mali particle-flow sample).
//
// v = amplitude * scale * curl(psi)(p), with the vector potential
//   psi(p) = (N1(p / scale), N2(p / scale), N3(p / scale))
// made of three independent gradient-noise channels. The curl uses the noise's
// exact gradients (no finite differences), so div v = 0 up to rounding.
// The factor `scale` cancels the 1/scale of the chain rule: `amplitude` is the
// typical speed in m/s whatever the feature size.
#pragma once

#include <cstdint>

#include "core/field/analytic_field.h"
#include "core/field/gradient_noise.h"

namespace sandstorm {

struct CurlNoiseParams {
  float scale = 2.0f;      // m: feature size (eddy diameter), > 0
  float amplitude = 1.0f;  // m/s: typical speed
  glm::vec3 offset{0.0f};  // m: shifts the pattern (animate it to make the field evolve)
  std::uint32_t seed = 7;
};

class CurlNoiseField final : public AnalyticField {
 public:
  explicit CurlNoiseField(const CurlNoiseParams& params);
  glm::vec3 evaluate(const glm::vec3& p) const override;
  const CurlNoiseParams& params() const { return params_; }

 private:
  CurlNoiseParams params_;
  GradientNoise n1_, n2_, n3_;
};

}  // namespace sandstorm
