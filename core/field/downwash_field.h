// DownwashField: the air a hovering helicopter rotor pushes down, turning
// into a radial wall jet along the ground. An engineering model, not CFD:
//
// Momentum theory gives the induced speed at the disc (radius R, area A = pi R^2)
//   v_h = sqrt(T / (2 rho A))
// for thrust T and air density rho. Below the disc (distance s, negative above)
// the column speeds up as the actuator-disc (vortex cylinder) solution says,
//   W(s) = v_h (1 + s / sqrt(s^2 + R^2))        (v_h at the disc, 2 v_h far below)
// with a Gaussian radial profile exp(-r^2 / a^2) whose width a^2 = R^2 v_h / W
// carries the disc's volume flow Q = pi R^2 v_h unchanged, and the radial inflow
//   u_r = -(W'(s) / 2) r exp(-r^2 / a^2)
// that makes the column exactly divergence-free (the slipstream contracts).
//
// Near the ground the column fades out over `groundLayer` metres (a smoothstep
// in the height above ground) and a radial wall jet carries the same flow Q
// outwards:
//   u_r = Q / (2 pi r delta e) * (h / delta) exp(1 - h / delta) * (1 - exp(-r^2 / a_g^2))
// with h the height above ground, delta = 0.1 R + 0.05 r its thickness (growing
// with r as wall jets do), and a_g the column width at the ground. Its flux
// through any cylinder r >> a_g is Q. Axis: the rotor turns about +z and
// blows towards -z; the ground is the plane z = ground.
#pragma once

#include "core/field/analytic_field.h"

namespace sandstorm {

struct DownwashParams {
  glm::vec3 hub{0.0f, 0.0f, 10.0f};  // m: centre of the rotor disc
  float radius = 5.0f;               // m: rotor radius R, > 0
  float thrust = 20000.0f;           // N: thrust T (about the weight), > 0
  float density = 1.225f;            // kg/m^3: air density rho, > 0
  float ground = 0.0f;               // m: height of the ground plane, below the hub
  float groundLayer = 5.0f;          // m: the column turns into the wall jet below this height
};

class DownwashField final : public AnalyticField {
 public:
  explicit DownwashField(const DownwashParams& params);
  glm::vec3 evaluate(const glm::vec3& p) const override;
  const DownwashParams& params() const { return params_; }

  float hoverInducedSpeed() const { return vh_; }  // v_h, m/s
  float volumeFlow() const { return flow_; }       // Q = pi R^2 v_h, m^3/s

 private:
  DownwashParams params_;
  float vh_ = 0.0f;
  float flow_ = 0.0f;
};

}  // namespace sandstorm
