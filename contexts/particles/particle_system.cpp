#include "contexts/particles/particle_system.h"

#include "core/util/log.h"

namespace sandstorm {

ParticleSystem::ParticleSystem(const ParticleState& initial, std::size_t capacity)
    : state_(initial), update_(capacity) {}

void ParticleSystem::setTerrain(std::shared_ptr<const HeightMap> terrain) { update_.setTerrain(std::move(terrain)); }

void ParticleSystem::advance(const FramePacket& packet) {
  if (packet.reset) update_.clear();
  // The main context validated every change; a replica applies them as they come.
  for (const StateChange& change : packet.changes) applyChange(state_, change);
  if (packet.fieldUpdate) {
    field_ = packet.fieldUpdate;
    update_.setField(field_->field, field_->placement);
    log::debug("frame ", packet.frame, ": field uploaded in ", update_.lastFieldUploadMs(), " ms");
  }
  update_.step(packet.step(), state_);
  frame_ = packet.frame;
}

void ParticleSystem::render(const ViewTargets& targets, std::uint32_t destination, glm::ivec2 origin) const {
  render_.draw(update_, targets, state_.render.mode);
  post_.draw(targets, destination, origin);
}

}  // namespace sandstorm
