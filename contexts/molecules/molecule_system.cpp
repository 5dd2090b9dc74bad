#include "contexts/molecules/molecule_system.h"

namespace sandstorm {

bool MoleculeSystem::wanted(const ParticleState& state) {
  for (const Emitter& e : state.emitters)
    if (e.kind == EmitterKind::Molecules) return true;
  return false;
}

MoleculeSystem::MoleculeSystem(std::size_t capacity, std::size_t capacityLimit,
                               const GpuTuning& tuning)
    : update_(capacity, capacityLimit, tuning) {}

void MoleculeSystem::setField(const FieldUpdate& field) {
  update_.setField(field.field, field.placement, field.next);
  update_.setEquation(field.equation);
}

}  // namespace sandstorm
