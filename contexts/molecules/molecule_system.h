// MoleculeSystem: one render context's molecules (the molecules paper): its
// MoleculeUpdate and MoleculeRenderer. A ParticleSystem makes one when its
// state first has a molecule emitter and keeps it from then on; it changes
// only by the frame packets the particles do, so every wall holds the same
// molecules. Needs its GL context current for every call.
#pragma once

#include <memory>

#include "contexts/molecules/molecule_renderer.h"
#include "contexts/molecules/molecule_update.h"
#include "core/sim/frame_packet.h"

namespace sandstorm {

class MoleculeSystem {
 public:
  // Whether a state emits molecules (a ParticleSystem then makes its MoleculeSystem).
  static bool wanted(const ParticleState& state);

  MoleculeSystem(std::size_t capacity, std::size_t capacityLimit, const GpuTuning& tuning);

  void setField(const FieldUpdate& field);
  void setTerrain(std::shared_ptr<const HeightMap> terrain) {
    update_.setTerrain(std::move(terrain));
  }
  void step(const SimStep& step, const ParticleState& state) { update_.step(step, state); }
  void clear() { update_.clear(); }
  // Into the view's particle buffers, after the particles.
  void draw(const ViewTargets& targets) const {
    renderer_.draw(update_, update_.moleculeBlock(), targets);
  }
  const MoleculeUpdate& update() const { return update_; }

 private:
  MoleculeUpdate update_;
  MoleculeRenderer renderer_;
};

}  // namespace sandstorm
