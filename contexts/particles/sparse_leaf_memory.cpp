#include "contexts/particles/sparse_leaf_memory.h"

#include <epoxy/gl.h>

#include <cstdint>

#include "core/util/error.h"

namespace sandstorm {

void SparseLeafMemory::bind(int in, std::size_t capacity) {
  if (capacity > capacity_) {
    const GLsizeiptr bytes = GLsizeiptr(capacity * sizeof(std::uint32_t));
    const std::uint32_t none = 0xffffffffu;  // field_sparse.glsl's kNoSparseLeaf
    glGetError();                            // start clean, to tell an allocation failure apart
    for (gl::Buffer& b : leaves_) {
      b = gl::createBuffer();
      glNamedBufferStorage(b.id(), bytes, nullptr, 0);
      glClearNamedBufferData(b.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
    }
    if (glGetError() == GL_OUT_OF_MEMORY)
      throw Error(concat("the GPU has no memory for the sparse grid's leaf of each of ", capacity,
                         " particles (", 2 * bytes >> 20,
                         " MiB); lower sim.maximum or run.capacity_limit"));
    capacity_ = capacity;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 9, leaves_[std::size_t(in)].id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 10, leaves_[std::size_t(1 - in)].id());
}

}  // namespace sandstorm
