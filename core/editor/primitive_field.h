// PrimitiveField: the velocity one field-editor primitive adds, in the room's
// frame (see field_primitive.h for what its numbers mean):
//   vortex   Lamb-Oseen line vortex: v = G/(2 pi rho) (1 - exp(-rho^2/R^2)) (a x rho^)
//            about the line through `position` along the unit axis a, with the
//            circulation G = 2 pi R S / (1 - 1/e), so the swirl at rho = R is S;
//            divergence-free, zero on the axis.
//   source   v = S (R / r)^2 r^ outside the core r >= R, S r / R r^ inside (a
//            Rankine source: uniform outflow in the core); S < 0 is a sink.
//   wind     v = S a^.
//   tornado  VortexField (core/field/vortex_field.h) with core R and spin S, its
//            range, height, pull and up in the default tornado's proportions.
//   sphere_flow  SphereFlowField: potential flow of speed S along a^ past a
//            sphere of radius R at `position`.
//   curl_noise   CurlNoiseField: eddies of size R and typical speed S, shifted
//            by `position`.
// A zero axis counts as +z. Inactive primitives (kind none, disabled) add nothing.
#pragma once

#include <memory>

#include "core/editor/field_primitive.h"
#include "core/field/analytic_field.h"

namespace sandstorm {

class PrimitiveField final : public AnalyticField {
 public:
  explicit PrimitiveField(const FieldPrimitive& primitive);
  ~PrimitiveField() override;
  glm::vec3 evaluate(const glm::vec3& p) const override;

 private:
  FieldPrimitive p_;
  glm::vec3 axis_;
  float circulation_ = 0.0f;                // vortex: G, m^2/s
  std::unique_ptr<AnalyticField> library_;  // tornado, sphere_flow, curl_noise
};

}  // namespace sandstorm
