// ParticleBackend: one context's particle buffers and the update that advances
// them. Two implementations keep the same semantics (ReferenceSimulator is the
// specification): ParticleGeoUpdate (transform feedback + geometry shaders,
// the thesis's design) and ParticleComputeUpdate (compute shaders).
//
// Records are ordered: the newborn of the last update first, then the
// survivors in their previous order. All calls need the context current.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "contexts/molecules/molecule_handles.h"
#include "contexts/shadows/shadow_handles.h"
#include "core/field/field_equation.h"
#include "core/field/field_placement.h"
#include "core/field/height_map.h"
#include "core/field/sparse_field.h"
#include "core/field/vector_field.h"
#include "core/sim/particle.h"
#include "core/sim/particle_state.h"
#include "core/sim/sim_step.h"

namespace sandstorm {

class ParticleBackend {
 public:
  virtual ~ParticleBackend() = default;

  // `next`: a time-varying field's next frame (same grid), blended by SimStep::fieldBlend.
  virtual void setField(std::shared_ptr<const VectorField> field, const FieldPlacement& placement,
                        std::shared_ptr<const VectorField> next = nullptr) = 0;
  // Once a frame, after any setField: the frame a time-varying field is
  // likely to need next (FramePacket::upcomingField; null: none), uploaded
  // ahead of need where the backend can. A hint: particles never depend on it.
  virtual void prefetchField(std::shared_ptr<const VectorField>) {}
  // An analytic field's equation: while state.field.mode is Equation, updates
  // evaluate it in place of the field's grid (whose bounds still apply). Null: none.
  virtual void setEquation(std::shared_ptr<const FieldEquation> equation) = 0;
  // A sparse grid (FieldUpdate::sparse) read in place of the field's grid,
  // whose bounds are its bounds. Null: none.
  virtual void setSparse(std::shared_ptr<const SparseField> sparse) = 0;
  virtual void setTerrain(std::shared_ptr<const HeightMap> terrain) = 0;
  // The live flow solver's grid on this GPU (a storage buffer in GpuField's
  // layout, the field's dims and bounds) read in place of the field's; 0:
  // the field again. False where this backend cannot read one (the field's
  // grid kept as a texture: transform feedback, or too large a grid); going
  // back to the field (0) every backend can.
  virtual bool setFieldBuffer(std::uint32_t buffer) { return buffer == 0; }
  // Whether step() blends a time-varying field's pair point by point into
  // one grid before sampling it (ParticleComputeUpdate, where the grids are
  // buffers: FieldPairBlend) rather than sampling both and blending the
  // samples; the CPU twin must do the same (PhysicsInputs::pointwiseBlend).
  // Asked after setField.
  virtual bool blendsPairPointwise(const ParticleState&) const { return false; }
  virtual void step(const SimStep& step, const ParticleState& state) = 0;
  virtual void clear() = 0;
  // Grows the buffers, keeping every live particle in place. Waits for the GPU.
  virtual void grow(std::size_t capacity) = 0;

  // Draws the current particles as GL_POINTS with the bound program, which
  // reads attribute 0 (position, life) and 1 (velocity, kind).
  virtual void draw() const = 0;

  // The current records for compute passes (ParticleSplat), without reading
  // anything back: records 0 .. count-1 of the two buffers, where count is the
  // uint at byte `countOffset` of `countBuffer` plus `countAdd`.
  struct Records {
    std::uint32_t positionLife = 0, velocityKind = 0;
    std::uint32_t countBuffer = 0;
    std::uint32_t countOffset = 0;
    std::uint32_t countAdd = 0;
    // Byte offset in `countBuffer` of a DrawArraysIndirectCommand drawing the
    // records, or -1: another context can draw them without reading anything back.
    std::int64_t drawCommand = -1;
    // Trails (ParticleTrails; compute backend, render.trail_length > 0): a
    // buffer of `trailLength` vec4 per record, slot `trailHead` the newest.
    std::uint32_t trails = 0;
    std::int32_t trailLength = 0, trailHead = 0;
  };
  virtual Records records() const = 0;

  // False for a wall that only draws another context's simulation (SharedParticles).
  virtual bool simulates() const { return true; }
  // After step(), with what the owner derived from this frame's records (the
  // shadow map) and its molecules: a shared simulation publishes them to its
  // readers here.
  virtual void publish(const ShadowHandles&, const MoleculeHandles&) {}
  // A reader's: the owner's shadow map and molecules of the frame it draws.
  virtual ShadowHandles sharedShadow() const { return {}; }
  virtual MoleculeHandles sharedMolecules() const { return {}; }
  // Called once a frame's every view is drawn (a shared simulation's readers fence here).
  virtual void endFrame() {}

  virtual std::size_t capacity() const = 0;
  // The live count of a recent update, known without waiting (a frame or two
  // old): for the statistics of the frame loop, which must never stall.
  virtual std::size_t lateCount() const = 0;
  // These wait for the GPU; for tests and dumps, not the frame loop.
  virtual std::size_t liveCount() const = 0;
  virtual std::vector<Particle> readBack() const = 0;
  virtual double lastFieldUploadMs() const = 0;
  virtual const char* name() const = 0;
};

}  // namespace sandstorm
