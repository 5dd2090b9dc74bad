#include "contexts/particles/particle_splat.h"

#include <epoxy/gl.h>

#include "contexts/particles/particle_backend.h"
#include "contexts/render/view_targets.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr std::size_t kChannels = 8;  // kSplatStride of splat_common.glsl

// Storage-buffer bindings of the splat shaders.
enum Binding : GLuint { kPositionLife = 0, kVelocityKind = 1, kCounts = 4, kDispatch = 5, kAccumulation = 6 };

}  // namespace

ParticleSplat::ParticleSplat()
    : prepare_(std::vector<std::string>{"splat_prepare.comp"}),
      splat_(std::vector<std::string>{"particle_splat.comp"}),
      resolve_(std::vector<std::string>{"particle_splat_resolve.comp"}),
      dispatch_(gl::createBuffer()) {
  glNamedBufferStorage(dispatch_.id(), 32, nullptr, 0);
}

void ParticleSplat::draw(const ParticleBackend& particles, const ViewTargets& targets, std::uint32_t sprite) const {
  const glm::ivec2 size = targets.size();
  const std::size_t pixels = std::size_t(size.x) * std::size_t(size.y);
  if (pixels > pixels_) {
    accumulation_ = gl::createBuffer();
    glGetError();
    glNamedBufferStorage(accumulation_.id(), GLsizeiptr(pixels * kChannels * 4), nullptr, 0);
    if (glGetError() == GL_OUT_OF_MEMORY) throw Error(concat("ParticleSplat: no GPU memory for ", pixels, " pixels"));
    const GLuint zero = 0;
    glClearNamedBufferData(accumulation_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    pixels_ = pixels;
  }
  const ParticleBackend::Records records = particles.records();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPositionLife, records.positionLife);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVelocityKind, records.velocityKind);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCounts, records.countBuffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDispatch, dispatch_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kAccumulation, accumulation_.id());

  prepare_.use();
  glProgramUniform1ui(prepare_.id(), 0, records.countOffset / 4);
  glProgramUniform1ui(prepare_.id(), 1, records.countAdd);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);

  splat_.use();
  glBindTextureUnit(2, sprite);
  glBindTextureUnit(3, targets.sceneDepth());
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, dispatch_.id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  resolve_.use();
  glProgramUniform2i(resolve_.id(), 0, size.x, size.y);
  glBindImageTexture(0, targets.particleColor(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glBindImageTexture(1, targets.particleNormal(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glDispatchCompute(GLuint((size.x + 15) / 16), GLuint((size.y + 15) / 16), 1);
  // ParticlePost reads the images as textures; the next splat adds to the zeroed sums.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
}

}  // namespace sandstorm
