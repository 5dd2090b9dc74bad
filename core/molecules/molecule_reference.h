// MoleculeReference: the CPU twin of the GPU's molecules
// (contexts/molecules/molecule_update.h), record for record.
//
// Molecules are kept as their members' records, molecule after molecule
// (molecule i's member j at record i * complexity + j), like the GPU's
// buffers. One update writes a new buffer:
//   1. molecule emitters, in order, write their newborn molecules
//      (birthMolecule), as many as their EmissionBudget grants under
//      molecules.maximum;
//   2. every molecule of the old buffer, in order, steps (advanceMolecule,
//      with its repulsion from the old buffer's centres); the dead are dropped
//      whole, the survivors follow the newborn in their order.
// A change of molecules.complexity starts afresh (no molecules), at the
// same frame in every context.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/molecules/molecule_physics.h"
#include "core/sim/emission_budget.h"
#include "core/sim/particle.h"
#include "core/sim/particle_state.h"
#include "core/sim/physics_world.h"
#include "core/sim/sim_step.h"

namespace sandstorm {

class MoleculeReference {
 public:
  // Capacities count molecules; `capacityLimit`: how far raising
  // molecules.maximum may grow it.
  explicit MoleculeReference(std::size_t capacity, std::size_t capacityLimit = 0);

  PhysicsWorld& world() { return world_; }
  void step(const SimStep& step, const ParticleState& state);
  void clear();

  std::span<const Particle> records() const { return records_; }
  int complexity() const { return complexity_; }
  std::size_t count() const {
    return complexity_ > 0 ? records_.size() / std::size_t(complexity_) : 0;
  }
  std::size_t capacity() const { return capacity_; }

  // Continues from `records` (the GPU's, read back), as many as it holds:
  // a comparison then measures one update's difference, not its growth
  // through the springs. Throws std::invalid_argument on a different count.
  void adopt(std::span<const Particle> records);

 private:
  std::size_t capacity_;
  std::size_t capacityLimit_;
  PhysicsWorld world_;
  int complexity_ = 0;
  std::vector<Particle> records_, next_;
  EmissionBudget budget_;
  std::size_t count1_ = 0, count2_ = 0;  // molecules after the last two updates
};

}  // namespace sandstorm
