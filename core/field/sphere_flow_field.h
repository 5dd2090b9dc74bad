// SphereFlowField: ideal (potential) flow past a sphere, plus the point source
// of the Mali particle-flow sample. Both parts are divergence-free outside the
// sphere.
//
// With x = p - center, r = |x|, the free stream U = speed * d^ and radius R:
//   stream:  v = U + (R^3 / 2) (U / r^3 - 3 (U . x) x / r^5)      (uniform flow + doublet)
//   source:  v = Q / (4 pi) * x / (r^2 + eps^2)^(3/2)              (gradient of -Q / (4 pi r))
// The stream part has zero normal velocity on the sphere r = R, stagnation
// points at x = -+R d^ and 1.5 |U| at the equator. Q is a volume rate (m^3/s):
// positive pushes away from the sphere. eps removes the source's singularity,
// as in the Mali sample. Inside the sphere (r < R) the field is zero.
#pragma once

#include "core/field/analytic_field.h"

namespace sandstorm {

struct SphereFlowParams {
  glm::vec3 center{0.0f};
  float radius = 1.0f;                    // m, > 0
  glm::vec3 direction{1.0f, 0.0f, 0.0f};  // of the free stream, not zero
  float speed = 2.0f;                     // m/s: free-stream speed (0: source only)
  float source = 0.0f;                    // m^3/s: source strength Q
  float epsilon = 0.1f;                   // m: source softening, >= 0
};

class SphereFlowField final : public AnalyticField {
 public:
  explicit SphereFlowField(const SphereFlowParams& params);
  glm::vec3 evaluate(const glm::vec3& p) const override;
  const SphereFlowParams& params() const { return params_; }

 private:
  SphereFlowParams params_;
  glm::vec3 stream_;
};

}  // namespace sandstorm
