// fluidForces(): what drives the live flow in a state, in the solver's
// (the field's) coordinates: the helicopter's rotor disc under its hub, an
// actuator disc pushing the helicopter's thrust (times solver.rotor_thrust)
// down through it. FluidDriver (the main context's CPU) and ParticleSystem
// (each GPU) both use it, so they solve the same flow.
#pragma once

#include "core/field/field_placement.h"
#include "core/field/height_map.h"
#include "core/sim/helicopter.h"
#include "core/sim/particle_state.h"
#include "core/solver/fluid_solver.h"

namespace sandstorm {

FluidForces fluidForces(const ParticleState& state, const HeightMap* terrain,
                        const FieldPlacement& placement, const HelicopterModel& model = {});

}  // namespace sandstorm
