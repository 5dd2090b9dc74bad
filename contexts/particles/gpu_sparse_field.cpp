#include "contexts/particles/gpu_sparse_field.h"

#include <epoxy/gl.h>

#include "core/util/error.h"

namespace sandstorm {

void GpuSparseField::show(std::shared_ptr<const SparseField> field) {
  if (field == holds_) return;
  buffer_ = {};
  holds_.reset();
  if (!field) return;
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  const GLint64 bytes = GLint64(field->byteSize());
  if (bytes > maxBlock)
    throw Error(concat("the sparse field's upload: its ", field->activeVoxelCount(),
                       " active voxels take ", bytes,
                       " bytes, beyond this GPU's largest storage buffer (", maxBlock,
                       " bytes); load it densely at a lower resolution (field.storage = "
                       "\"dense\", field.resolution)"));
  buffer_ = gl::createBuffer();
  glGetError();
  glNamedBufferStorage(buffer_.id(), GLsizeiptr(bytes), field->words().data(), 0);
  if (glGetError() != GL_NO_ERROR) {
    buffer_ = {};
    throw Error(concat("the sparse field's upload: no GPU memory for its ", bytes,
                       " bytes; load it densely at a lower resolution (field.storage = "
                       "\"dense\", field.resolution)"));
  }
  holds_ = std::move(field);
}

void GpuSparseField::bind() const {
  if (buffer_) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 14, buffer_.id());
}

}  // namespace sandstorm
