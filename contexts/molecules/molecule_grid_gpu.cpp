#include "contexts/molecules/molecule_grid_gpu.h"

#include <epoxy/gl.h>

#include <bit>

namespace sandstorm {

MoleculeGridGpu::MoleculeGridGpu()
    : keys_(std::vector<std::string>{"molecule_grid_keys.comp"}),
      starts_(std::vector<std::string>{"molecule_grid_starts.comp"}) {}

std::uint32_t MoleculeGridGpu::tableMask(std::size_t capacity) {
  return std::uint32_t(std::bit_ceil(std::max<std::size_t>(capacity, 256))) - 1u;
}

void MoleculeGridGpu::build(std::size_t capacity, std::uint32_t positions, int inSet,
                            std::uint32_t control, std::uint32_t countOffset) {
  if (capacity != capacity_) {
    const auto storage = [](gl::Buffer& b, std::size_t bytes) {
      b = gl::createBuffer();
      glNamedBufferStorage(b.id(), GLsizeiptr(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
    };
    storage(centres_, capacity * 16);
    storage(sortKeys_, capacity * 4);
    storage(sortValues_, capacity * 4);
    storage(table_, (std::size_t(tableMask(capacity)) + 1) * 4);
    capacity_ = capacity;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, positions);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, centres_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, sortKeys_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 9, sortValues_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 10, table_.id());
  const GLuint groups = GLuint((capacity + 255) / 256);
  keys_.use();
  glProgramUniform1i(keys_.id(), 0, inSet);
  glDispatchCompute(groups, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  sort_.sortCounted(sortKeys_.id(), sortValues_.id(), capacity, control, countOffset);
  const GLuint none = 0xffffffffu;
  glClearNamedBufferData(table_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  // The sort used bindings of its own: bind the grid again for the passes after it.
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, control);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, centres_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, sortKeys_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 9, sortValues_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 10, table_.id());
  starts_.use();
  glProgramUniform1i(starts_.id(), 0, inSet);
  glDispatchCompute(groups, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace sandstorm
