// ReferenceSimulator: the CPU twin of the GPU particle system.
//
// It performs the GPU update's steps in the GPU's order, so its buffer matches
// the GPU's record for record. One update writes a new buffer:
//   1. emitters, in order, write their newborn particles (birth()), as many as
//      the EmissionBudget grants;
//   2. every particle of the old buffer, in order, ages and moves (advance());
//      the dead are dropped, the survivors follow the newborn in their order.
// Emitters of kind molecules are MoleculeReference's (core/molecules/).
// It exists for tests and as the readable specification of the update.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/sim/emission_budget.h"
#include "core/sim/particle.h"
#include "core/sim/particle_state.h"
#include "core/sim/physics_world.h"
#include "core/sim/sim_step.h"

namespace sandstorm {

class ReferenceSimulator {
 public:
  // `capacityLimit`: how far the capacity may grow when sim.maximum exceeds it.
  explicit ReferenceSimulator(std::size_t capacity, std::size_t capacityLimit = 0);

  void setField(std::shared_ptr<const VectorField> field, const FieldPlacement& placement = {},
                std::shared_ptr<const VectorField> next = nullptr);
  // A sparse grid sampled in place of the field (whose bounds are its bounds).
  void setSparse(std::shared_ptr<const SparseField> sparse) { world_.setSparse(std::move(sparse)); }
  void setTerrain(std::shared_ptr<const HeightMap> terrain);
  // How a time-varying field's pair is blended: as the GPU backend it is
  // compared with does (ParticleBackend::blendsPairPointwise).
  void setPointwiseBlend(bool pointwise) { world_.setPointwiseBlend(pointwise); }
  void step(const SimStep& step, const ParticleState& state);
  void clear();

  std::span<const Particle> particles() const { return particles_; }
  std::size_t capacity() const { return capacity_; }

  // Continues from `particles` (another simulator's, read back): as many as
  // it holds, in its order. So a GPU whose sqrt and division are not IEEE's
  // is compared one update at a time, not through the growth of differences
  // over many. Throws std::invalid_argument on a different count.
  void adopt(std::span<const Particle> particles);

 private:
  std::size_t capacity_;
  std::size_t capacityLimit_;
  PhysicsWorld world_;
  std::vector<Particle> particles_;
  std::vector<Particle> next_;
  EmissionBudget budget_;
  std::size_t count1_ = 0;  // particle count after the previous update
  std::size_t count2_ = 0;  // ... and after the one before
};

}  // namespace sandstorm
