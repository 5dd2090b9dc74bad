#include "core/solver/fluid_forces.h"

#include <numbers>

namespace sandstorm {

FluidForces fluidForces(const ParticleState& state, const HeightMap* terrain,
                        const FieldPlacement& placement, const HelicopterModel& model) {
  FluidForces forces;
  const HelicopterSettings& h = state.helicopter;
  if (!h.enabled) return forces;
  const float ground = terrain ? terrain->heightAt({h.x, h.y}) : 0.0f;
  forces.rotorCentre = placement.toLocal({h.x, h.y, ground + h.altitude});
  forces.rotorRadius = model.rotorRadius / placement.scale;
  // Momentum theory's actuator disc: the pressure jump is thrust / area; over
  // the air's density it is m^2/s^2, which the field's frame scales by 1/scale^2.
  constexpr float kAirDensity = 1.225f;  // kg/m^3, sea level
  const float area = std::numbers::pi_v<float> * model.rotorRadius * model.rotorRadius;
  const float thrust = helicopterEffects(h, model).thrust * state.solver.rotorThrust;
  forces.rotorPressure = thrust / (area * kAirDensity) / (placement.scale * placement.scale);
  return forces;
}

}  // namespace sandstorm
