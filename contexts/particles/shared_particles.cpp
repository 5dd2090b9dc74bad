#include "contexts/particles/shared_particles.h"

#include <epoxy/gl.h>

#include "core/util/error.h"

namespace sandstorm {

SharingBackend::SharingBackend(std::unique_ptr<ParticleBackend> inner,
                               std::shared_ptr<SimulationShare> share)
    : inner_(std::move(inner)), share_(std::move(share)) {
  if (inner_->records().drawCommand < 0)
    throw Error(
        concat("run.shared_simulation: the '", inner_->name(),
               "' backend cannot be drawn from another context; use run.backend = \"compute\""));
}

void SharingBackend::step(const SimStep& step, const ParticleState& state) {
  share_->waitForReaders(step.frame);  // readers are done with the buffers this update overwrites
  inner_->step(step, state);
  frame_ = step.frame;
}

void SharingBackend::publish(const ShadowHandles& shadow, const MoleculeHandles& molecules) {
  share_->publish(frame_,
                  {inner_->records(), inner_->capacity(), inner_->lateCount(), shadow, molecules});
}

SharedParticles::SharedParticles(std::shared_ptr<SimulationShare> share, int reader)
    : share_(std::move(share)),
      reader_(reader),
      vao_(gl::createVertexArray()),
      staging_(gl::createBuffer()) {
  for (GLuint a = 0; a < 2; ++a) {
    glEnableVertexArrayAttrib(vao_.id(), a);
    glVertexArrayAttribFormat(vao_.id(), a, 4, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao_.id(), a, a);
  }
  glNamedBufferStorage(staging_.id(), 16, nullptr, GL_DYNAMIC_STORAGE_BIT | GL_CLIENT_STORAGE_BIT);
}

void SharedParticles::step(const SimStep& step, const ParticleState&) {
  current_ = share_->acquire(step.frame);
  frame_ = step.frame;
  holding_ = true;
  glVertexArrayVertexBuffer(vao_.id(), 0, current_.records.positionLife, 0, sizeof(glm::vec4));
  glVertexArrayVertexBuffer(vao_.id(), 1, current_.records.velocityKind, 0, sizeof(glm::vec4));
}

void SharedParticles::endFrame() {
  if (!holding_) return;
  share_->release(reader_, frame_);
  holding_ = false;
}

void SharedParticles::draw() const {
  if (current_.records.countBuffer == 0) return;
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, current_.records.countBuffer);
  glDrawArraysIndirect(GL_POINTS,
                       reinterpret_cast<const void*>(std::uintptr_t(current_.records.drawCommand)));
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindVertexArray(0);
}

std::size_t SharedParticles::liveCount() const {
  if (current_.records.countBuffer == 0) return 0;
  // Through a buffer of this context's: reading the owner's control buffer
  // directly could make the driver move it to host memory.
  std::uint32_t count = 0;
  glCopyNamedBufferSubData(current_.records.countBuffer, staging_.id(),
                           current_.records.countOffset, 0, 4);
  glGetNamedBufferSubData(staging_.id(), 0, 4, &count);
  return std::size_t(count) + current_.records.countAdd;
}

std::vector<Particle> SharedParticles::readBack() const {
  const std::size_t count = liveCount();
  std::vector<Particle> particles(count);
  if (count == 0) return particles;
  const GLsizeiptr bytes = GLsizeiptr(count * sizeof(glm::vec4));
  gl::Buffer copy = gl::createBuffer();
  glNamedBufferStorage(copy.id(), 2 * bytes, nullptr, GL_CLIENT_STORAGE_BIT);
  glCopyNamedBufferSubData(current_.records.positionLife, copy.id(), 0, 0, bytes);
  glCopyNamedBufferSubData(current_.records.velocityKind, copy.id(), 0, bytes, bytes);
  std::vector<glm::vec4> data(2 * count);
  glGetNamedBufferSubData(copy.id(), 0, 2 * bytes, data.data());
  for (std::size_t i = 0; i < count; ++i)
    particles[i] = Particle{data[i], data[count + i]};
  return particles;
}

}  // namespace sandstorm
