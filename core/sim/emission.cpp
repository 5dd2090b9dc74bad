#include "core/sim/emission.h"

#include <algorithm>
#include <cmath>

namespace sandstorm {

std::uint32_t emissionCount(const Emitter& e, float dt, Seed seed, std::uint32_t frame,
                            std::uint32_t emitterIndex) {
  if (!e.enabled || dt <= 0.0f) return 0;
  const glm::vec4 r = randomUniform(seed, frame, emitterIndex, 0, RngStream::kEmission);
  const double mean = double(e.rate) * dt;
  const double spread = double(e.rateVariance) * dt * (2.0 * r.x - 1.0);
  const double n = std::floor(std::max(0.0, mean + spread) + r.y);
  return std::uint32_t(std::min(n, double(kMaxEmissionPerFrame)));
}

std::vector<std::uint32_t> emissionCounts(const ParticleState& state, float dt, Seed seed,
                                          std::uint32_t frame) {
  std::vector<std::uint32_t> counts(state.emitters.size(), 0);
  if (!state.sim.emitting || state.sim.paused) return counts;
  for (std::size_t e = 0; e < counts.size(); ++e)
    counts[e] = emissionCount(state.emitters[e], dt, seed, frame, std::uint32_t(e));
  return counts;
}

std::vector<std::uint32_t> emissionOfKind(const std::vector<std::uint32_t>& counts,
                                          const ParticleState& state, EmitterKind kind) {
  std::vector<std::uint32_t> mine = counts;
  for (std::size_t e = 0; e < mine.size(); ++e)
    if (e >= state.emitters.size() || state.emitters[e].kind != kind) mine[e] = 0;
  return mine;
}

}  // namespace sandstorm
