// SimStep: what one frame's particle update needs besides the state and the
// field, identical for every context and for the CPU reference.
#pragma once

#include <cstdint>
#include <vector>

#include "core/sim/counter_rng.h"

namespace sandstorm {

struct SimStep {
  std::uint32_t frame = 0;
  float dt = 0.0f;  // simulated seconds; 0 while paused (nothing moves, dies or is born)
  Seed seed;
  std::vector<std::uint32_t> emission;  // Reeves' count per emitter (emission.h)
  float fieldBlend = 0.0f;              // weight towards a time-varying field's next frame
  double time = 0.0;  // simulated seconds before this step (a field expression's t)
};

}  // namespace sandstorm
