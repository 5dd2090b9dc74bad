// Streaklines: for each enabled point emitter, the last `length` points it
// released, one a frame, each carried since by the flow as a particle is
// (advance() in core/sim/particle_physics.h, without terrain), joined in
// release order. In a steady wind they lie on the streamline through the
// emitter; in a changing flow they show where the released dust is now.
// StreaklineReference is the CPU twin of the walls' GPU streaklines
// (contexts/scene/streakline_renderer, shaders/streak_update.comp).
#pragma once

#include <vector>

#include "core/sim/particle_physics.h"
#include "core/sim/particle_state.h"

namespace sandstorm {

struct StreakPoint {
  glm::vec3 position{0.0f};
  glm::vec3 velocity{0.0f};
  bool valid = false;
};

class StreaklineReference {
 public:
  // One frame: every point moves (when in.dt > 0), then each point emitter
  // releases a new one at the ring's new head. `length` (2..1024) change: start afresh.
  void step(const ParticleState& state, const PhysicsInputs& in);
  void clear() { rings_.clear(); }

  // Emitter e's points, newest first, the valid ones (a ring of `length`).
  std::vector<StreakPoint> line(int emitter) const;
  int head() const { return head_; }

 private:
  int length_ = 0;
  int head_ = 0;
  std::vector<std::vector<StreakPoint>> rings_;  // [emitter][slot]
};

// Whether emitter e releases streak points: enabled, and a point emitter.
bool streaks(const Emitter& emitter);

}  // namespace sandstorm
