// VortexRingField: a horizontal vortex ring (a smoke ring lying on its side),
// the recirculation that forms where a rotor's wall jet meets still air and
// rolls up and back inwards: it is what lifts a brownout dust cloud off the
// ground. In the vertical half-plane through the ring's axis, with d the
// distance from the ring's core circle (radius `ringRadius`, height `height`),
// the flow turns about the core at
//   speed = strength * d * core / (d^2 + core^2) * 2 / core   (peak `strength` at d = core)
// outwards along the ground below the core, up on its outer side, inwards above.
#pragma once

#include "core/field/analytic_field.h"

namespace sandstorm {

struct VortexRingParams {
  glm::vec3 center{0.0f};    // on the ground, under the ring's axis
  float ringRadius = 12.0f;  // m
  float height = 4.0f;       // m: the core circle above `center`
  float core = 4.0f;         // m: core radius (where the speed peaks)
  float strength = 4.0f;     // m/s: peak speed
};

class VortexRingField final : public AnalyticField {
 public:
  explicit VortexRingField(const VortexRingParams& params);
  glm::vec3 evaluate(const glm::vec3& p) const override;

 private:
  VortexRingParams params_;
};

}  // namespace sandstorm
