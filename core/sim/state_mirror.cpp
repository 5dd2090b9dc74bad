#include "core/sim/state_mirror.h"

#include "core/sim/state_change.h"

namespace sandstorm {

void StateMirror::apply(std::shared_ptr<const FramePacket> packet) {
  for (const StateChange& change : packet->changes)
    applyChange(state_, change);
  if (packet->fieldUpdate) field_ = packet->fieldUpdate;
  last_ = std::move(packet);
}

}  // namespace sandstorm
