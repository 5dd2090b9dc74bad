#include "contexts/particles/particle_environment.h"

#include <epoxy/gl.h>

#include <chrono>

#include "core/util/error.h"

namespace sandstorm {

void ParticleEnvironment::setField(std::shared_ptr<const VectorField> field,
                                   const FieldPlacement& placement,
                                   std::shared_ptr<const VectorField> next) {
  if (field && next &&
      (field->dims() != next->dims() || field->bounds().min != next->bounds().min ||
       field->bounds().max != next->bounds().max))
    throw Error("a time-varying field's frames must share one grid");
  const auto start = std::chrono::steady_clock::now();
  // Each frame from the grid that has it: the pair's two swap places (a
  // step forwards or backwards), or the prefetch hands over its grid.
  if (field && fieldGrid_.holds() != field && nextFieldGrid_.holds() == field)
    std::swap(fieldGrid_, nextFieldGrid_);
  else if (next && next != field && nextFieldGrid_.holds() != next && fieldGrid_.holds() == next)
    std::swap(fieldGrid_, nextFieldGrid_);
  if (field && fieldGrid_.holds() != field) prefetch_.takeInto(fieldGrid_, field);
  if (next && nextFieldGrid_.holds() != next) prefetch_.takeInto(nextFieldGrid_, next);
  fieldGrid_.show(field);
  nextFieldGrid_.show(next);
  lastUploadMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  field_ = std::move(field);
  nextField_ = std::move(next);
  placement_ = placement;
}

void ParticleEnvironment::setTerrain(std::shared_ptr<const HeightMap> terrain) {
  terrain_ = std::move(terrain);
  if (terrain_) terrainTexture_.upload(*terrain_);
}

bool ParticleEnvironment::blendsPair(const ParticleState& state) const {
  return field_ && nextField_ && fieldBuffer_ == 0 && !sparse_.holds() &&
         !(state.field.mode == FieldMode::Equation && equation_.equation()) &&
         state.field.mode != FieldMode::Expression &&
         fieldGrid_.storage() != GpuField::Storage::Texture &&
         nextFieldGrid_.storage() == fieldGrid_.storage() && fieldGrid_.holds() == field_ &&
         nextFieldGrid_.holds() == nextField_;
}

bool ParticleEnvironment::blendPair(const ParticleState& state, float weight) {
  blended_ = blendsPair(state);
  if (blended_)
    pairBlend_.blend(fieldGrid_, nextFieldGrid_, weight);
  else
    pairBlend_.release();  // neither its GPU memory nor the pair's steps held for nothing
  return blended_;
}

void ParticleEnvironment::describe(SimBlockInputs& inputs) const {
  inputs.field = field_.get();
  // The live flow's grid has no next frame; a blended pair is one grid
  // whose validity is both frames' (blendedNext: their masks count).
  inputs.nextField = fieldBuffer_ != 0 || blended_ ? nullptr : nextField_.get();
  inputs.blendedNext = blended_ ? nextField_.get() : nullptr;
  inputs.sparse = fieldBuffer_ != 0 || !field_ ? nullptr : sparse_.holds().get();
  inputs.placement = placement_;
  inputs.terrain = terrain_.get();
}

FieldRead ParticleEnvironment::bind(const ParticleState& state) const {
  if (terrain_) terrainTexture_.bind(1);
  if (fieldBuffer_ != 0 && field_ && readsBuffers()) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 14, fieldBuffer_);
    return FieldRead::Grid;
  }
  if (blended_) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 14, pairBlend_.buffer());
    return FieldRead::Grid;
  }
  if (field_) fieldGrid_.bind(GpuField::Slot::Current);
  if (nextField_) nextFieldGrid_.bind(GpuField::Slot::Next);
  if (equation_.bindIfUsed(state)) return FieldRead::Equation;
  if (field_ && sparse_.holds()) {
    sparse_.bind();
    return FieldRead::Sparse;
  }
  return FieldRead::Grid;
}

}  // namespace sandstorm
