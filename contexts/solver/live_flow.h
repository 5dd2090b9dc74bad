// LiveFlow: the live flow solver on one GPU (solver.enabled with
// solver.device = gpu), for the ParticleSystem that runs the GPU's
// simulation. It starts a GpuFluidSolver from the field in use, steps it
// every solver.every frames on their simulated time, before the particles
// move, and gives the grid the particle update reads in place of the
// field's. Every wall (and rank) applies the same packets, so every GPU
// solves the same flow step for step (no atomics: the same programs give the
// same numbers). A new field (a file loaded) starts it afresh from that one.
// Needs its GL context current.
#pragma once

#include <cstdint>
#include <memory>

#include "contexts/solver/gpu_fluid_solver.h"
#include "core/sim/frame_packet.h"
#include "core/sim/particle_state.h"

namespace sandstorm {

class LiveFlow {
 public:
  // Steps when due; returns the storage buffer of the flow's grid (the
  // field's layout), or 0 while the solver is off (read the field's own).
  std::uint32_t advance(const ParticleState& state, const FieldUpdate* field,
                        const HeightMap* terrain, float simDt);
  // The particle update could not read the grid (run.backend = tf-gs, or a
  // grid kept as a texture): stop, saying so once.
  void refuse(const char* why);
  const GpuFluidSolver* solver() const { return solver_.get(); }

 private:
  std::unique_ptr<GpuFluidSolver> solver_;
  std::shared_ptr<const VectorField> base_;  // the field's grid it started from
  float pendingDt_ = 0.0f;
  int pendingFrames_ = 0;
  bool refused_ = false;
};

}  // namespace sandstorm
