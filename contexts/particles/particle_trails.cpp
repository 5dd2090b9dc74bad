#include "contexts/particles/particle_trails.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <limits>

#include "contexts/gl/out_of_memory.h"
#include "core/util/error.h"

namespace sandstorm {

ParticleTrails::ParticleTrails()
    : program_(std::vector<std::string>{"trail_update.comp"}),
      dispatch_(std::vector<std::string>{"trail_dispatch.comp"}),
      dispatchArgs_(gl::createBuffer()) {
  glNamedBufferStorage(dispatchArgs_.id(), 16, nullptr, 0);
}

void ParticleTrails::prepare(std::size_t capacity, int length) {
  length = std::clamp(length, 1, kMaxLength);
  if (capacity != capacity_ || length != length_) {
    // trail_update.comp numbers the slots with a uint.
    if (capacity * std::size_t(length) > std::numeric_limits<std::uint32_t>::max() - 255)
      throw Error(concat("render.trail_length ", length, ": ", capacity,
                         " particles' trails hold more than 2^32 positions; shorten the trails "
                         "or lower sim.maximum"));
    const GLsizeiptr ringBytes = GLsizeiptr(capacity) * length * GLsizeiptr(sizeof(glm::vec4));
    const gl::OutOfMemoryCheck memory;
    source_ = gl::createBuffer();
    glNamedBufferStorage(source_.id(), GLsizeiptr(capacity) * 4, nullptr, 0);
    for (gl::Buffer& ring : rings_) {
      ring = gl::createBuffer();
      glNamedBufferStorage(ring.id(), ringBytes, nullptr, 0);
    }
    if (memory.failed())
      throw Error(concat("render.trail_length ", length, ": ", capacity, " particles' trails need ",
                         ringBytes * 2 / (1 << 20),
                         " MiB the GPU does not have; shorten the trails or lower sim.maximum"));
    capacity_ = capacity;
    length_ = length;
    fresh_ = true;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, source_.id());
}

void ParticleTrails::advance(std::uint32_t positions, std::uint32_t born, std::uint32_t countBuffer,
                             int countIndex, std::uint32_t countAdd) {
  const int next = 1 - current_;
  head_ = fresh_ ? 0 : (head_ + 1) % length_;
  // One invocation a slot of the live records, counted on the GPU.
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, countBuffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 13, dispatchArgs_.id());
  dispatch_.use();
  glProgramUniform1ui(dispatch_.id(), 0, GLuint(countIndex));
  glProgramUniform1ui(dispatch_.id(), 1, countAdd);
  glProgramUniform1ui(dispatch_.id(), 2, GLuint(length_));
  glProgramUniform1ui(dispatch_.id(), 3, GLuint(capacity_));
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, positions);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, source_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, rings_[std::size_t(current_)].id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, rings_[std::size_t(next)].id());
  program_.use();
  glProgramUniform1ui(program_.id(), 1, born);
  glProgramUniform1i(program_.id(), 2, length_);
  glProgramUniform1i(program_.id(), 3, head_);
  glProgramUniform1i(program_.id(), 4, fresh_ ? 1 : 0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, dispatchArgs_.id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  current_ = next;
  fresh_ = false;
}

std::vector<std::vector<glm::vec3>> ParticleTrails::readBack(std::size_t count) const {
  return read(ring(), length_, head_, count);
}

std::vector<std::vector<glm::vec3>> ParticleTrails::read(std::uint32_t ring, int length, int head,
                                                         std::size_t count) {
  if (ring == 0 || length <= 0) return {};
  std::vector<glm::vec4> slots(count * std::size_t(length));
  if (!slots.empty())
    glGetNamedBufferSubData(ring, 0, GLsizeiptr(slots.size() * sizeof(glm::vec4)), slots.data());
  std::vector<std::vector<glm::vec3>> trails(count);
  for (std::size_t i = 0; i < count; ++i)
    for (int j = 0; j < length; ++j) {
      const glm::vec4 slot =
          slots[i * std::size_t(length) + std::size_t((head - j + length) % length)];
      if (slot.w > 0.5f) trails[i].push_back(glm::vec3(slot));
    }
  return trails;
}

}  // namespace sandstorm
