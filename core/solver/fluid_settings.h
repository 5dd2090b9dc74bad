// FluidSettings: the live flow solver's attributes (solver.* in the table of
// dynamic attributes, [solver] in a configuration, the menu's Field section);
// core/solver/fluid_solver.h says what each does.
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

// Where the flow is solved: on each GPU beside the particle update (every
// GPU steps it alike from the same packets), or on the main context's CPU,
// whose grids then travel to the walls as a time-varying field's frames do.
// Auto: the application picks (app_run.cpp): gpu where the walls' OpenGL is a
// GPU's, cpu where it runs in software (llvmpipe), where the CPU's threads are faster.
enum class FluidDevice : int { Gpu = 0, Cpu = 1, Auto = 2 };

struct FluidSettings {
  bool enabled = false;  // the field is the solver's (it starts from the field's grid)
  FluidDevice device = FluidDevice::Auto;
  int iterations = 40;       // pressure iterations a step (red-black SOR)
  float relaxation = 1.7f;   // the SOR factor, 1 (Gauss-Seidel) .. 1.95
  int every = 1;             // frames a step (its dt is their simulated time)
  glm::vec3 wind{0.0f};      // m/s blowing in at the domain's upwind sides
  bool closed = false;       // every side a wall (a room); else open but for the floor
  float rotorThrust = 1.0f;  // x the helicopter's thrust, pushed through its rotor disc
  float viscosity = 0.0f;    // m^2/s (kinematic; the scheme adds its own numerical share)
  float vorticity = 0.0f;    // vorticity confinement's epsilon (Fedkiw et al. 2001), 0: off
  float turbulence = 0.0f;   // forced eddies' intensity, a fraction of the local speed; 0: off
  float eddySize = 3.0f;     // m: the forced eddies' size
};

}  // namespace sandstorm
