#include "core/molecules/molecule_reference.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/molecules/molecule_grid.h"
#include "core/sim/capacity.h"
#include "core/sim/emission.h"

namespace sandstorm {

MoleculeReference::MoleculeReference(std::size_t capacity, std::size_t capacityLimit)
    : capacity_(capacity), capacityLimit_(std::max(capacity, capacityLimit)) {}

void MoleculeReference::adopt(std::span<const Particle> records) {
  if (records.size() != records_.size())
    throw std::invalid_argument("adopt: " + std::to_string(records.size()) + " records for " +
                                std::to_string(records_.size()));
  std::copy(records.begin(), records.end(), records_.begin());
}

void MoleculeReference::clear() {
  records_.clear();
  budget_.reset();
  count1_ = count2_ = 0;
}

void MoleculeReference::step(const SimStep& step, const ParticleState& state) {
  const MoleculeSettings& ms = state.molecules;
  capacity_ = grownCapacity(capacity_, ms.maximum, capacityLimit_);
  if (complexity_ != ms.complexity) {
    clear();
    complexity_ = ms.complexity;
  }
  if (step.dt <= 0.0f) return;
  const PhysicsInputs in = world_.inputs(step, state);
  const MoleculeParams params = moleculeParams(ms, step.dt);
  const MoleculeShape& shape = moleculeShape(complexity_);
  const std::size_t n = std::size_t(complexity_);

  const std::size_t limit = std::min(std::size_t(std::max(ms.maximum, 0)), capacity_);
  const std::vector<std::uint32_t> granted = budget_.allocate(
      emissionOfKind(step.emission, state, EmitterKind::Molecules), limit, count2_);
  next_.clear();
  std::uint32_t born = 0;
  std::vector<Particle> members(n);
  for (std::size_t e = 0; e < granted.size() && e < state.emitters.size(); ++e) {
    for (std::uint32_t k = 0; k < granted[e]; ++k) {
      birthMolecule(state.emitters[e], step.seed, step.frame, std::uint32_t(e), k, shape, ms.size,
                    members);
      settleNewbornMolecule(members, in);
      next_.insert(next_.end(), members.begin(), members.end());
    }
    born += granted[e];
  }
  budget_.recordEmitted(born);

  const std::size_t count = records_.size() / n;
  std::vector<glm::vec3> centres;
  if (params.repulsion) {
    centres.resize(count);
    for (std::size_t i = 0; i < count; ++i)
      centres[i] = moleculeCentre(std::span<const Particle>(records_).subspan(i * n, n));
  }
  const MoleculeGrid grid(centres, params.repulsionRadius);
  for (std::size_t i = 0; i < count; ++i) {
    std::copy_n(records_.begin() + std::ptrdiff_t(i * n), n, members.begin());
    const glm::vec3 push =
        params.repulsion ? grid.displacement(i, params.repulsionShare) : glm::vec3(0.0f);
    if (advanceMolecule(members, in, params, push))
      next_.insert(next_.end(), members.begin(), members.end());
  }
  std::swap(records_, next_);
  count2_ = count1_;
  count1_ = records_.size() / n;
}

}  // namespace sandstorm
