// ParticleState: everything that decides what the particle system does, apart
// from the field: the simulation and render settings and the emitters.
// The main context owns the authoritative copy; every render context holds a
// replica that it changes only by applying the main context's frame packets.
#pragma once

#include <vector>

#include "core/editor/field_primitive.h"
#include "core/flow/slice_settings.h"
#include "core/flow/streamline_settings.h"
#include "core/molecules/molecule_settings.h"
#include "core/obstacles/obstacle.h"
#include "core/sim/emitter.h"
#include "core/sim/helicopter.h"
#include "core/sim/sim_settings.h"
#include "core/solver/fluid_settings.h"

namespace sandstorm {

struct ParticleState {
  static constexpr int kMaxEmitters = 16;
  static constexpr int kMaxObstacles = 8;
  static constexpr int kMaxPrimitives = 8;

  SimSettings sim;
  RenderSettings render;
  FieldPlayback field;
  HelicopterSettings helicopter;
  StreamlineSettings streamlines;
  SliceSettings slice;
  ProbeSettings probe;
  MoleculeSettings molecules;
  FluidSettings solver;  // the live flow solver (app/fluid_driver.h)
  std::vector<Emitter> emitters{Emitter{}};
  std::vector<Obstacle> obstacles;  // from the configuration's [[obstacle]]s; edited, never added
  // The field editor's primitives (core/editor): always kMaxPrimitives slots,
  // kind none where empty; the main context adds the active ones to the field.
  std::vector<FieldPrimitive> primitives = std::vector<FieldPrimitive>(std::size_t(kMaxPrimitives));
};

}  // namespace sandstorm
