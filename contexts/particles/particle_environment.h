// ParticleEnvironment: what particles move through, on the GPU, for either
// update backend: the field's grid (and a time-varying field's next frame),
// its placement, the frame after those uploaded ahead of need
// (GridPrefetch), its equation (field.mode = equation), a sparse grid read in
// place of the dense one, and the terrain.
#pragma once

#include <memory>

#include "contexts/particles/field_equation_buffer.h"
#include "contexts/particles/field_pair_blend.h"
#include "contexts/particles/gpu_field.h"
#include "contexts/particles/gpu_sparse_field.h"
#include "contexts/particles/grid_prefetch.h"
#include "contexts/particles/sim_block.h"
#include "core/field/field_placement.h"

namespace sandstorm {

// How an update's program reads the field: the grid (a texture or, with
// FIELD_BUFFER or FIELD_BUFFER_HALF, a buffer), the equation
// (FIELD_EQUATION) or the sparse grid (FIELD_SPARSE).
enum class FieldRead { Grid, Equation, Sparse };

// The define a program reading the field so needs: FIELD_EQUATION,
// FIELD_SPARSE, FIELD_BUFFER (a grid kept as a buffer of vec4),
// FIELD_BUFFER_HALF (of halves), or none (a texture).
inline const char* fieldReadDefine(FieldRead read, GpuField::Storage storage) {
  if (read == FieldRead::Equation) return "FIELD_EQUATION";
  if (read == FieldRead::Sparse) return "FIELD_SPARSE";
  if (storage == GpuField::Storage::HalfBuffer) return "FIELD_BUFFER_HALF";
  return storage == GpuField::Storage::Buffer ? "FIELD_BUFFER" : nullptr;
}

class ParticleEnvironment {
 public:
  // `storage`: how the field's grid is kept if it can be (GpuField); the
  // backend's shaders read it as gridStorage() says (FIELD_BUFFER in
  // shaders/particle_physics.glsl). `uploads`: copies steps ahead of need
  // (GridPrefetch); null: this thread does.
  explicit ParticleEnvironment(GpuField::Storage storage, UploadThread* uploads = nullptr)
      : fieldGrid_(storage), nextFieldGrid_(storage), prefetch_(storage, uploads) {}

  // Throws Error when `next` has another grid than `field`. A frame already on
  // the GPU is not uploaded again (a sequence steps A,B -> B,C, or backwards
  // B,C -> A,B), nor one uploaded ahead of need (prefetch()).
  void setField(std::shared_ptr<const VectorField> field, const FieldPlacement& placement,
                std::shared_ptr<const VectorField> next);
  // Once a frame, after setField: the frame a time-varying field is likely to
  // need next (FramePacket::upcomingField; null: none), uploaded ahead of need.
  void prefetch(std::shared_ptr<const VectorField> upcoming) {
    prefetch_.advance(std::move(upcoming));
  }
  void setEquation(std::shared_ptr<const FieldEquation> equation) {
    equation_.set(std::move(equation));
  }
  // A sparse grid (FieldUpdate::sparse) read in place of the field's grid,
  // whose bounds are its bounds; null: the grid again.
  void setSparse(std::shared_ptr<const SparseField> sparse) { sparse_.show(std::move(sparse)); }
  // Whether the sparse grid bound by bind() lies in one storage buffer
  // (GpuSparseField::inOneBuffer).
  bool sparseInOneBuffer() const { return sparse_.inOneBuffer(); }
  void setTerrain(std::shared_ptr<const HeightMap> terrain);
  // A storage buffer holding the field's grid in GpuField's Buffer layout
  // (vec4: the live flow solver's points, GpuFluidSolver), read in place of
  // the uploaded field's (whose dims and bounds it shares); 0: the uploaded
  // field again. Only where the grid is kept in a buffer (readsBuffers());
  // no next frame, no equation while it is set.
  void setFieldBuffer(std::uint32_t buffer) { fieldBuffer_ = buffer; }
  // Whether the programs read the grid from storage buffers, so that a
  // buffer given to setFieldBuffer can take its place.
  bool readsBuffers() const { return fieldGrid_.storage() != GpuField::Storage::Texture; }
  std::uint32_t fieldBuffer() const { return fieldBuffer_; }

  // Before describe() and bind(), for an update that samples a time-varying
  // field's grids: blends the pair into one grid (FieldPairBlend) where both
  // are kept in buffers and the update reads the grid, so that describe()
  // and bind() give the blend as the field, with no next frame. False, and
  // the pair as before, otherwise (no next frame, textures, the equation, a
  // sparse grid, the live flow's buffer). `weight`: SimStep::fieldBlend.
  bool blendPair(const ParticleState& state, float weight);
  // Whether blendPair would blend now (the CPU twin then samples the blend:
  // PhysicsInputs::pointwiseBlend).
  bool blendsPair(const ParticleState& state) const;

  // The environment's part of an update's inputs.
  void describe(SimBlockInputs& inputs) const;
  // Binds the field's grids (GpuField::bind) or its sparse grid, the terrain
  // (texture unit 1) and, when state.field.mode asks for it, the equation;
  // returns how the update's program must read the field.
  FieldRead bind(const ParticleState& state) const;

  // How the field's grid is read (both frames of a time-varying field share a
  // grid, so a storage): a buffer given to setFieldBuffer holds vec4s.
  GpuField::Storage gridStorage() const {
    return fieldBuffer_ != 0 && readsBuffers() ? GpuField::Storage::Buffer : fieldGrid_.storage();
  }

  // What the last setField took: uploads, or finishing a frame on its way.
  double lastUploadMs() const { return lastUploadMs_; }

 private:
  std::shared_ptr<const VectorField> field_, nextField_;
  FieldPlacement placement_;
  std::shared_ptr<const HeightMap> terrain_;
  GpuField fieldGrid_, nextFieldGrid_;
  GridPrefetch prefetch_;
  double lastUploadMs_ = 0.0;
  TerrainTexture terrainTexture_;
  FieldEquationBuffer equation_;
  GpuSparseField sparse_;
  std::uint32_t fieldBuffer_ = 0;
  FieldPairBlend pairBlend_;
  bool blended_ = false;  // the last blendPair blended
};

}  // namespace sandstorm
