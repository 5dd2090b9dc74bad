#include "app/fluid_driver.h"

#include <chrono>

#include "core/obstacles/collision_shapes.h"
#include "core/solver/fluid_forces.h"
#include "core/util/log.h"

namespace sandstorm {

FluidDriver::FluidDriver(std::shared_ptr<const HeightMap> terrain, HelicopterModel model)
    : terrain_(std::move(terrain)), model_(model) {}

void FluidDriver::update(MainContext& main, const FramePacket& packet) {
  const ParticleState state = main.state();
  const std::shared_ptr<const FieldUpdate> current = main.field();
  // Another field took over (a file loaded, the helicopter's wash baked): it is the base now.
  const bool replaced = solver_ && lastField_ && (!current || current->field != lastField_);
  // On the GPU (solver.device = gpu) every wall solves it beside its particles.
  if (!state.solver.enabled || state.solver.device != FluidDevice::Cpu) {
    if (solver_) {
      if (!replaced) main.setField(*base_);
      log::info("solver: off; ",
                replaced ? "the field set since stays" : "the field it started from");
      solver_.reset();
      lastField_.reset();
    }
    return;
  }
  if (replaced) {
    log::info("solver: a new field; the flow starts afresh from it");
    solver_.reset();
  }
  if (!solver_) {
    base_ = main.field();
    if (!base_ || !base_->field) return;
    const VectorField& f = *base_->field;
    solver_ = std::make_unique<FluidSolver>(f.bounds(), f.dims(), &f);
    pendingDt_ = 0.0f;
    pendingFrames_ = 0;
    log::info("solver: a ", f.dims().x, "x", f.dims().y, "x", f.dims().z,
              " flow from the field in use, stepped every ", state.solver.every, " frame(s)");
  }
  pendingDt_ += packet.simDt;
  if (++pendingFrames_ < state.solver.every || !(pendingDt_ > 0.0f)) return;

  const auto start = std::chrono::steady_clock::now();
  const FieldPlacement& placement = base_->placement;
  solver_->setSolids(terrain_.get(), collisionShapes(state, terrain_.get()), placement);
  FluidSettings settings = state.solver;
  settings.wind = placement.vectorToLocal(state.solver.wind);
  solver_->step(pendingDt_, settings, fluidForces(state, terrain_.get(), placement, model_));
  lastField_ = std::make_shared<const VectorField>(solver_->velocityField());
  main.setField(FieldUpdate{.field = lastField_, .placement = placement});
  lastStepMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  log::debug("solver: step of ", pendingDt_, " s in ", lastStepMs_, " ms, max |div| ",
             solver_->maxDivergence(), " /s, fastest ", lastField_->maxMagnitude(), " m/s");
  pendingDt_ = 0.0f;
  pendingFrames_ = 0;
}

}  // namespace sandstorm
