// Emission counts (Reeves 1983): each emitter emits, per frame,
//   n = rate * dt + rateVariance * dt * (2r - 1)
// particles, r uniform in [0, 1), rounded stochastically (floor(n + r'), so the
// mean is exact at any frame rate without carrying a remainder between frames).
// The main context computes these once per frame and ships them in the frame
// packet; render contexts never draw random numbers of their own.
#pragma once

#include <cstdint>
#include <vector>

#include "core/sim/counter_rng.h"
#include "core/sim/particle_state.h"

namespace sandstorm {

// More than this per emitter per frame is capped (about 1.7e7).
inline constexpr std::uint32_t kMaxEmissionPerFrame = 1u << 24;

std::uint32_t emissionCount(const Emitter& emitter, float dt, Seed seed, std::uint32_t frame,
                            std::uint32_t emitterIndex);

// One count per emitter; all zero when emission is stopped or time is paused.
std::vector<std::uint32_t> emissionCounts(const ParticleState& state, float dt, Seed seed,
                                          std::uint32_t frame);

// `counts` with the emitters of another kind at 0: the particle systems take
// the particle emitters' counts, the molecule systems the molecule emitters'.
std::vector<std::uint32_t> emissionOfKind(const std::vector<std::uint32_t>& counts,
                                          const ParticleState& state, EmitterKind kind);

}  // namespace sandstorm
