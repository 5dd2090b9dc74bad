// FluidDriver: the live flow solver in the main context (core/solver). While
// solver.enabled, it starts a FluidSolver from the field in use (its grid,
// placement and velocities), steps it every solver.every frames on their
// simulated time (the helicopter's rotor pushing air down through its disc,
// the terrain and the obstacles solid, the wind blowing in), and hands each
// step's velocity grid to the main context as the field, so every wall and
// rank gets the same flow at the same frame (grids travel as time-varying
// fields' frames do). Turned off, it gives the field it started from back
// (unless another field replaced its own meanwhile); a field loaded while it
// runs starts it afresh from that field.
// Main thread; call once a frame after MainContext::next(), with its packet.
#pragma once

#include <memory>

#include "core/field/height_map.h"
#include "core/sim/frame_packet.h"
#include "core/sim/helicopter.h"
#include "core/sim/main_context.h"
#include "core/solver/fluid_solver.h"

namespace sandstorm {

class FluidDriver {
 public:
  FluidDriver(std::shared_ptr<const HeightMap> terrain, HelicopterModel model = {});
  void update(MainContext& main, const FramePacket& packet);
  // The running solver (null while off): tests and statistics.
  const FluidSolver* solver() const { return solver_.get(); }
  double lastStepMs() const { return lastStepMs_; }

 private:
  std::shared_ptr<const HeightMap> terrain_;
  HelicopterModel model_;
  std::unique_ptr<FluidSolver> solver_;
  std::shared_ptr<const FieldUpdate> base_;       // the field it started from
  std::shared_ptr<const VectorField> lastField_;  // the grid it handed over last
  float pendingDt_ = 0.0f;
  int pendingFrames_ = 0;
  double lastStepMs_ = 0.0;
};

}  // namespace sandstorm
