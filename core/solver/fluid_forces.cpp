#include "core/solver/fluid_forces.h"

namespace sandstorm {

FluidForces fluidForces(const ParticleState& state, const HeightMap* terrain,
                        const FieldPlacement& placement, const HelicopterModel& model) {
  FluidForces forces;
  const HelicopterSettings& h = state.helicopter;
  if (!h.enabled) return forces;
  const float ground = terrain ? terrain->heightAt({h.x, h.y}) : 0.0f;
  forces.rotorCentre = placement.toLocal({h.x, h.y, ground + h.altitude});
  forces.rotorRadius = model.rotorRadius / placement.scale;
  forces.rotorAcceleration = state.solver.rotorAcceleration * h.throttle / placement.scale;
  return forces;
}

}  // namespace sandstorm
