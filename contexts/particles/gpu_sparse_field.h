// GpuSparseField: a SparseField's NanoVDB words in a shader storage buffer,
// read by FIELD_SPARSE programs (shaders/field_sparse.glsl) at binding 14, the
// binding a dense grid's buffer takes in the programs that read one. Needs its
// GL context current for every call.
#pragma once

#include <memory>

#include "contexts/gl/objects.h"
#include "core/field/sparse_field.h"

namespace sandstorm {

class GpuSparseField {
 public:
  // Uploads a grid it does not hold yet; null drops it. Throws Error naming
  // the sizes when the grid passes the GPU's storage-buffer limit
  // (GL_MAX_SHADER_STORAGE_BLOCK_SIZE) or its memory.
  void show(std::shared_ptr<const SparseField> field);
  const std::shared_ptr<const SparseField>& holds() const { return holds_; }
  void bind() const;

 private:
  std::shared_ptr<const SparseField> holds_;
  gl::Buffer buffer_;
};

}  // namespace sandstorm
