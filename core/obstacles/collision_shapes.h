// What the particles collide with this frame: the enabled obstacles of the
// state, then the helicopter's parts (helicopter_shape.h). Everything that
// steps particles (the CPU reference, SimBlock for the GPU, the streamline
// tracer) takes its list from here, so they all see the same solids.
#pragma once

#include <vector>

#include "core/field/height_map.h"
#include "core/obstacles/obstacle.h"
#include "core/sim/particle_state.h"

namespace sandstorm {

// At most this many (the state's obstacles and the helicopter's parts).
inline constexpr int kMaxCollisionShapes = 16;

std::vector<Obstacle> collisionShapes(const ParticleState& state, const HeightMap* terrain);

}  // namespace sandstorm
