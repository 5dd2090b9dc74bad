// How the dust blocks the light (issue 13's opacity shadow maps): the model
// the GPU's shadow passes implement and the tests check against.
//
// The light is directional: it comes from `towardsLight` (render.light_direction).
// A particle of diameter s and opacity a blocks it as a disc of area
// pi (s/2)^2 whose every point lets exp(-tau) through, with
//   tau = -ln(1 - a * puffCoverage())      (the puff's mean coverage),
// so its cross-section (the optical depth it adds, integrated over area) is
//   sigma = pi (s/2)^2 * tau * density     (render.shadow_density scales it).
// A cloud of n particles per cubic metre then lets exp(-n sigma d) through
// at depth d along the light: the Beer-Lambert law the tests check.
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

// The light's frame: `right` and `up` span the shadow map, `toLight` is the
// unit direction towards the light. Right-handed, deterministic (the same
// on every wall and rank).
struct LightFrame {
  glm::vec3 right, up, toLight;
};
LightFrame lightFrame(glm::vec3 towardsLight);

// sigma above, in square metres.
float particleCrossSection(float diameter, float opacity, float density);

}  // namespace sandstorm
