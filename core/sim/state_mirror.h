// StateMirror: the state and field as of the last packet applied, kept by a
// process that only receives packets (a cluster rank other than 0), so its
// own legend and probe show what its walls show. The packets carry the same
// validated changes every wall applies, so the mirror equals the main
// context's state() after the same packets.
#pragma once

#include <memory>
#include <utility>

#include "core/sim/frame_packet.h"
#include "core/sim/particle_state.h"

namespace sandstorm {

class StateMirror {
 public:
  explicit StateMirror(ParticleState initial) : state_(std::move(initial)) {}

  void apply(std::shared_ptr<const FramePacket> packet);
  const ParticleState& state() const { return state_; }
  std::shared_ptr<const FieldUpdate> field() const { return field_; }
  const FramePacket* last() const { return last_.get(); }

 private:
  ParticleState state_;
  std::shared_ptr<const FieldUpdate> field_;
  std::shared_ptr<const FramePacket> last_;
};

}  // namespace sandstorm
