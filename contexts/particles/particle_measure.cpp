#include "contexts/particles/particle_measure.h"

#include <epoxy/gl.h>

#include <cstring>

#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr GLsizeiptr kResult = 4 * sizeof(std::uint32_t);

float fromOrdered(std::uint32_t o) {
  const std::uint32_t bits = (o & 0x80000000u) != 0u ? o & 0x7fffffffu : ~o;
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

}  // namespace

ParticleMeasure::ParticleMeasure()
    : program_(std::vector<std::string>{"particle_measure.comp"}),
      result_(gl::createBuffer()),
      readBack_(gl::createBuffer()) {
  glNamedBufferStorage(result_.id(), kResult, nullptr, GL_DYNAMIC_STORAGE_BIT);
  const GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
  glNamedBufferStorage(readBack_.id(), kResult * kSlots, nullptr, flags);
  mapped_ = static_cast<const std::uint32_t*>(
      glMapNamedBufferRange(readBack_.id(), 0, kResult * kSlots, flags));
  if (!mapped_) throw Error("ParticleMeasure: cannot map its read-back buffer");
}

void ParticleMeasure::measure(std::uint32_t frame, const ParticleBackend::Records& r,
                              std::size_t capacity, std::optional<glm::vec4> probe) {
  latest();                                 // collect what finished before the slot is reused
  if (fences_[std::size_t(next_)]) return;  // every slot still in flight: skip a frame
  // near 0, least at the top, greatest at the bottom, live 0.
  const std::uint32_t start[4] = {0u, 0xffffffffu, 0u, 0u};
  glNamedBufferSubData(result_.id(), 0, kResult, start);
  program_.use();
  const GLuint groups = GLuint((capacity + 255) / 256), row = std::min<GLuint>(groups, 32768u);
  glProgramUniform1ui(program_.id(), 0, r.countOffset / 4);
  glProgramUniform1ui(program_.id(), 1, r.countAdd);
  const glm::vec4 p =
      probe ? glm::vec4(glm::vec3(*probe), probe->w * probe->w) : glm::vec4(0, 0, 0, -1);
  glProgramUniform4f(program_.id(), 2, p.x, p.y, p.z, p.w);
  glProgramUniform1ui(program_.id(), 3, row);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, r.positionLife);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, r.velocityKind);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, r.countBuffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 10, result_.id());
  glDispatchCompute(row, (groups + row - 1) / row, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  glCopyNamedBufferSubData(result_.id(), readBack_.id(), 0, kResult * next_, kResult);
  fences_[std::size_t(next_)] = gl::createFence();
  frames_[std::size_t(next_)] = frame;
  next_ = (next_ + 1) % kSlots;
}

std::optional<ParticleMeasurement> ParticleMeasure::latest() {
  for (int k = 0; k < kSlots; ++k) {
    gl::Sync& fence = fences_[std::size_t(k)];
    if (!fence) continue;
    const GLenum state = glClientWaitSync(reinterpret_cast<GLsync>(fence.handle()), 0, 0);
    if (state != GL_ALREADY_SIGNALED && state != GL_CONDITION_SATISFIED) continue;
    fence = gl::Sync();
    const std::uint32_t* v = mapped_ + 4 * k;
    ParticleMeasurement m{frames_[std::size_t(k)], v[3], v[0], 0.0f, 0.0f};
    if (v[1] <= v[2]) {
      m.least = fromOrdered(v[1]);
      m.greatest = fromOrdered(v[2]);
    }
    if (!latest_ || m.frame > latest_->frame) latest_ = m;
  }
  return latest_;
}

}  // namespace sandstorm
