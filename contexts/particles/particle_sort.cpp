#include "contexts/particles/particle_sort.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace sandstorm {

ParticleSort::ParticleSort() : keys_({"particle_depth_keys.comp"}), command_(gl::createBuffer()) {
  glNamedBufferStorage(command_.id(), 16, nullptr, 0);
}

void ParticleSort::reserve(std::size_t capacity) {
  capacity = std::max<std::size_t>(capacity, 1);
  if (capacity <= capacity_) return;
  capacity_ = capacity;
  keyBuffer_ = gl::createBuffer();
  values_ = gl::createBuffer();
  glNamedBufferStorage(keyBuffer_.id(), GLsizeiptr(capacity * 4), nullptr, 0);
  glNamedBufferStorage(values_.id(), GLsizeiptr(capacity * 4), nullptr, 0);
}

void ParticleSort::sort(const ParticleBackend::Records& r, std::size_t capacity) {
  reserve(capacity);
  keys_.use();
  const GLuint groups = GLuint((std::max<std::size_t>(capacity, 1) + 255) / 256),
               row = std::min<GLuint>(groups, 32768u);
  glProgramUniform1ui(keys_.id(), 0, r.countOffset / 4);
  glProgramUniform1ui(keys_.id(), 1, r.countAdd);
  glProgramUniform1ui(keys_.id(), 2, row);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, r.positionLife);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, r.countBuffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, keyBuffer_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, values_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, command_.id());
  glDispatchCompute(row, (groups + row - 1) / row, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  // The command's first word is the count: the sort reads it there.
  radix_.sortCounted(keyBuffer_.id(), values_.id(), capacity, command_.id(), 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

}  // namespace sandstorm
