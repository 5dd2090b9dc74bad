// GpuSparseField: a SparseField's NanoVDB words in shader storage buffers,
// read by FIELD_SPARSE programs (shaders/field_sparse.glsl) at bindings 14 and
// 15 (the bindings a dense grid's buffers take in the programs that read
// one): the words below 2 GiB in the first, the rest in the second, so a
// sparse grid may take up to 4 GiB (NanoVDB's GLSL addresses bytes with 32
// bits) where one buffer holds 2 GiB (NVIDIA). Needs its GL context current
// for every call.
#pragma once

#include <memory>

#include "contexts/gl/objects.h"
#include "core/field/sparse_field.h"

namespace sandstorm {

class GpuSparseField {
 public:
  // Uploads a grid it does not hold yet; null drops it. Throws Error naming
  // the sizes when the grid passes what two storage buffers hold
  // (GL_MAX_SHADER_STORAGE_BLOCK_SIZE each, 4 GiB in all) or the GPU's memory.
  void show(std::shared_ptr<const SparseField> field);
  const std::shared_ptr<const SparseField>& holds() const { return holds_; }
  // Whether the words lie in one buffer: programs may then be compiled with
  // FIELD_SPARSE_ONE_BUFFER, whose reads skip choosing a buffer.
  bool inOneBuffer() const { return low_ && !high_; }
  void bind() const;

 private:
  std::shared_ptr<const SparseField> holds_;
  gl::Buffer low_, high_;
};

}  // namespace sandstorm
