#include "core/sim/reference_simulator.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/sim/capacity.h"
#include "core/sim/emission.h"
#include "core/sim/particle_physics.h"

namespace sandstorm {

ReferenceSimulator::ReferenceSimulator(std::size_t capacity, std::size_t capacityLimit)
    : capacity_(capacity), capacityLimit_(std::max(capacity, capacityLimit)) {
  particles_.reserve(capacity);
  next_.reserve(capacity);
}

void ReferenceSimulator::setField(std::shared_ptr<const VectorField> field,
                                  const FieldPlacement& placement,
                                  std::shared_ptr<const VectorField> next) {
  world_.setField(std::move(field), placement, std::move(next));
}

void ReferenceSimulator::setTerrain(std::shared_ptr<const HeightMap> terrain) {
  world_.setTerrain(std::move(terrain));
}

void ReferenceSimulator::step(const SimStep& step, const ParticleState& state) {
  capacity_ = grownCapacity(capacity_, state.sim.maximum, capacityLimit_);
  if (step.dt <= 0.0f) return;
  const PhysicsInputs in = world_.inputs(step, state);

  const std::size_t limit = std::min(std::size_t(std::max(state.sim.maximum, 0)), capacity_);
  const std::vector<std::uint32_t> granted = budget_.allocate(
      emissionOfKind(step.emission, state, EmitterKind::Particles), limit, count2_);
  next_.clear();
  std::uint32_t born = 0;
  for (std::size_t e = 0; e < granted.size() && e < state.emitters.size(); ++e) {
    for (std::uint32_t k = 0; k < granted[e]; ++k) {
      Particle p = birth(state.emitters[e], step.seed, step.frame, std::uint32_t(e), k);
      settleNewborn(p, in);
      next_.push_back(p);
    }
    born += granted[e];
  }
  budget_.recordEmitted(born);
  for (Particle p : particles_)
    if (advance(p, in)) next_.push_back(p);
  std::swap(particles_, next_);
  count2_ = count1_;
  count1_ = particles_.size();
}

void ReferenceSimulator::adopt(std::span<const Particle> particles) {
  if (particles.size() != particles_.size())
    throw std::invalid_argument("adopt: " + std::to_string(particles.size()) + " particles for " +
                                std::to_string(particles_.size()));
  std::copy(particles.begin(), particles.end(), particles_.begin());
}

void ReferenceSimulator::clear() {
  particles_.clear();
  budget_.reset();
  count1_ = count2_ = 0;
}

}  // namespace sandstorm
