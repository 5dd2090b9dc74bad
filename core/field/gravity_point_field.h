// GravityPointField: the gravity point of the texture-vs-equation thesis
// (appendix B), a velocity or acceleration towards a centre.
//
// With d = center - p:
//   v = power * rpercent * d / |d|,   rpercent = clamp((range - |d|) / range, 0, 1)
// so the pull is strongest next to the centre and fades linearly to zero at
// `range`. A negative power repels. Mass plays no part (not Newtonian gravity).
// At the centre itself, where d / |d| has no direction, v = 0.
#pragma once

#include "core/field/analytic_field.h"

namespace sandstorm {

struct GravityPointParams {
  glm::vec3 center{0.0f};
  float range = 4.0f;  // m: radius of influence, > 0
  float power = 2.0f;  // m/s (or m/s^2): strength at the centre; < 0 repels
};

class GravityPointField final : public AnalyticField {
 public:
  explicit GravityPointField(const GravityPointParams& params);
  glm::vec3 evaluate(const glm::vec3& p) const override;
  const GravityPointParams& params() const { return params_; }

 private:
  GravityPointParams params_;
};

}  // namespace sandstorm
