// wandHandles: what the tracked wand can grab and carry, in the order its
// index in WandRay::emitter (a handle's index) counts them: every emitter
// (emitter.N.position), every enabled obstacle and active field-editor
// primitive (obstacle.N.position, primitive.N.position), then, while shown, the streamline rake's
// ends (streamlines.from, streamlines.to), the slice plane's point (slice.origin) and, with a
// probe, its set point (probe.position). Each is a Vec3 attribute, so a carry is a validated,
// recorded change like any other.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/sim/particle_state.h"

namespace sandstorm {

struct WandHandle {
  std::string key;     // the attribute it moves
  glm::vec3 position;  // world (the particles' coordinates)
};

std::vector<WandHandle> wandHandles(const ParticleState& state);

}  // namespace sandstorm
