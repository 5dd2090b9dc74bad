#include "core/flow/streaklines.h"

#include <algorithm>

namespace sandstorm {

bool streaks(const Emitter& e) {
  return e.enabled && e.shape == EmitterShape::Point;
}

void StreaklineReference::step(const ParticleState& state, const PhysicsInputs& in) {
  const int length = std::clamp(state.render.streakLength, 2, 1024);
  if (length != length_ || rings_.size() != std::size_t(ParticleState::kMaxEmitters)) {
    length_ = length;
    head_ = length - 1;
    rings_.assign(ParticleState::kMaxEmitters, std::vector<StreakPoint>(std::size_t(length)));
  }
  if (!(in.dt > 0.0f)) return;  // paused: nothing moves or is released
  PhysicsInputs noTerrain = in;
  noTerrain.terrain = nullptr;
  head_ = (head_ + 1) % length_;
  for (int e = 0; e < ParticleState::kMaxEmitters; ++e) {
    std::vector<StreakPoint>& ring = rings_[std::size_t(e)];
    for (int k = 0; k < length_; ++k) {
      StreakPoint& s = ring[std::size_t(k)];
      if (k == head_) {
        const bool releases =
            e < int(state.emitters.size()) && streaks(state.emitters[std::size_t(e)]);
        s = releases ? StreakPoint{state.emitters[std::size_t(e)].position,
                                   state.emitters[std::size_t(e)].velocity, true}
                     : StreakPoint{};
        continue;
      }
      if (!s.valid) continue;
      Particle p{glm::vec4(s.position, 1e30f), glm::vec4(s.velocity, 1e30f)};
      s.valid = advance(p, noTerrain);
      s.position = p.position();
      s.velocity = p.velocity();
    }
  }
}

std::vector<StreakPoint> StreaklineReference::line(int emitter) const {
  std::vector<StreakPoint> out;
  if (emitter < 0 || std::size_t(emitter) >= rings_.size()) return out;
  for (int j = 0; j < length_; ++j) {
    const StreakPoint& s =
        rings_[std::size_t(emitter)][std::size_t((head_ - j + length_) % length_)];
    if (s.valid) out.push_back(s);
  }
  return out;
}

}  // namespace sandstorm
