// VortexField: the tornado-like vortex of the texture-vs-equation thesis
// (appendix B), as a velocity field in m/s.
//
// With t = p - center, the axis point a = (t . d) d for the unit axis d, the
// radial offset r = t - a and its length rho:
//   v = falloff * (spin * (d x r^) - pull * r^ + up * d)      for 0 <= t . d <= height
//   v = 0                                                       elsewhere
// where falloff = clamp((range - rho) / range, 0, 1) is the thesis's "rpercent".
// Inside `core` the spin and pull grow linearly from zero (a Rankine core), so
// the field is continuous on the axis, where the thesis's unit vectors are not.
// A negative spin turns the other way, as the thesis's clockwise flag does.
#pragma once

#include "core/field/analytic_field.h"

namespace sandstorm {

struct VortexParams {
  glm::vec3 center{0.0f};
  glm::vec3 axis{0.0f, 0.0f, 1.0f};
  float range = 4.0f;   // m: radius of influence
  float height = 8.0f;  // m: length of the funnel along the axis
  float core = 0.6f;    // m: radius of the solid-body core
  float spin = 6.0f;    // m/s: tangential speed
  float pull = 1.5f;    // m/s: inward speed
  float up = 2.5f;      // m/s: speed along the axis
};

class VortexField final : public AnalyticField {
 public:
  explicit VortexField(const VortexParams& params);
  glm::vec3 evaluate(const glm::vec3& p) const override;
  const VortexParams& params() const { return params_; }

 private:
  VortexParams params_;
  glm::vec3 axis_;
};

}  // namespace sandstorm
