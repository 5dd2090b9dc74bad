#include "contexts/solver/live_flow.h"

#include "core/obstacles/collision_shapes.h"
#include "core/solver/fluid_forces.h"
#include "core/util/log.h"

namespace sandstorm {

std::uint32_t LiveFlow::advance(const ParticleState& state, const FieldUpdate* field,
                                const HeightMap* terrain, float simDt) {
  const bool wanted = state.solver.enabled && state.solver.device == FluidDevice::Gpu && field &&
                      field->field && !refused_;
  if (!state.solver.enabled) refused_ = false;  // asked again next time
  if (!wanted) {
    solver_.reset();
    base_.reset();
    return 0;
  }
  if (!solver_ || base_ != field->field) {
    base_ = field->field;
    solver_ = std::make_unique<GpuFluidSolver>(base_->bounds(), base_->dims(), base_.get());
    pendingDt_ = 0.0f;
    pendingFrames_ = 0;
  }
  pendingDt_ += simDt;
  if (++pendingFrames_ >= state.solver.every && pendingDt_ > 0.0f) {
    solver_->setSolids(terrain, collisionShapes(state, terrain), field->placement);
    FluidSettings settings = state.solver;
    settings.wind = field->placement.vectorToLocal(state.solver.wind);
    solver_->step(pendingDt_, settings, fluidForces(state, terrain, field->placement));
    pendingDt_ = 0.0f;
    pendingFrames_ = 0;
  }
  return solver_->pointBuffer();
}

void LiveFlow::refuse(const char* why) {
  if (!refused_) log::warn("solver.device = gpu: ", why, "; use solver.device = cpu");
  refused_ = true;
  solver_.reset();
  base_.reset();
}

}  // namespace sandstorm
