#include "contexts/particles/gpu_sparse_field.h"

#include <epoxy/gl.h>

#include <algorithm>

#include "core/util/error.h"

namespace sandstorm {
namespace {

// Where the words divide between the two buffers: kSparseSplitWords of
// shaders/field_sparse.glsl, in bytes (2 GiB less 1 MiB, within NVIDIA's
// storage-buffer limit of 2 GiB less one byte).
constexpr GLint64 kSplitBytes = GLint64(0x1FFC0000) * 4;
// NanoVDB's GLSL addresses bytes with 32 bits.
constexpr GLint64 kMaxBytes = GLint64(1) << 32;

gl::Buffer upload(const std::uint32_t* words, GLint64 bytes, GLint64 total) {
  gl::Buffer buffer = gl::createBuffer();
  glGetError();
  glNamedBufferStorage(buffer.id(), GLsizeiptr(bytes), words, 0);
  if (glGetError() != GL_NO_ERROR)
    throw Error(concat("the sparse field's upload: no GPU memory for its ", total,
                       " bytes; load it densely at a lower resolution (field.storage = "
                       "\"dense\", field.resolution)"));
  return buffer;
}

}  // namespace

void GpuSparseField::show(std::shared_ptr<const SparseField> field) {
  if (field == holds_) return;
  low_ = {};
  high_ = {};
  holds_.reset();
  if (!field) return;
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  const GLint64 bytes = GLint64(field->byteSize());
  // One buffer below the split (the shader never reads the second); two past it.
  const GLint64 fits = maxBlock >= kSplitBytes ? std::min(kSplitBytes + maxBlock, kMaxBytes)
                                               : std::min(maxBlock, kSplitBytes);
  if (bytes > fits)
    throw Error(concat("the sparse field's upload: its ", field->activeVoxelCount(),
                       " active voxels take ", bytes, " bytes, beyond the ", fits,
                       " this GPU's storage buffers hold for a sparse grid; load it densely at a "
                       "lower resolution (field.storage = \"dense\", field.resolution)"));
  const std::uint32_t* words = field->words().data();
  low_ = upload(words, std::min(bytes, kSplitBytes), bytes);
  if (bytes > kSplitBytes) high_ = upload(words + kSplitBytes / 4, bytes - kSplitBytes, bytes);
  holds_ = std::move(field);
}

void GpuSparseField::bind() const {
  if (!low_) return;
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 14, low_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 15, high_ ? high_.id() : low_.id());
}

}  // namespace sandstorm
