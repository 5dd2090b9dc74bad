#include "contexts/shadows/opacity_shadow_map.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <numbers>

#include "core/light/light_model.h"
#include "core/light/puff_sprite.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

// Storage-buffer bindings of the shadow passes (beyond the records' 0, 1 and 4).
enum Binding : GLuint {
  kPositionLife = 0,
  kVelocityKind = 1,
  kCounts = 4,
  kExtent = 14,
  kBlockOut = 15,
  kLayerSums = 16
};
constexpr GLuint kBlockBinding = 4;  // uniform: shadow_block.glsl
constexpr GLuint kTextureUnit = 7;
constexpr GLuint kMaxGroups = 2048;  // the record passes loop over the rest

void uniform3(const gl::Program& p, GLint location, glm::vec3 v) {
  glProgramUniform3f(p.id(), location, v.x, v.y, v.z);
}

}  // namespace

void ShadowHandles::bind() const {
  glBindBufferBase(GL_UNIFORM_BUFFER, kBlockBinding, block);
  glBindTextureUnit(kTextureUnit, texture);
}

OpacityShadowMap::OpacityShadowMap()
    : bounds_(std::vector<std::string>{"shadow_bounds.comp"}),
      frame_(std::vector<std::string>{"shadow_frame.comp"}),
      splat_(std::vector<std::string>{"shadow_splat.comp"}),
      accumulate_(std::vector<std::string>{"shadow_accumulate.comp"}),
      extent_(gl::createBuffer()),
      block_(gl::createBuffer()) {
  const GLuint reset[6] = {~0u, ~0u, ~0u, 0u, 0u, 0u};
  glNamedBufferStorage(extent_.id(), sizeof(reset), reset, 0);
  const float off[20] = {};  // right.w = 0: no shadows until the first build
  glNamedBufferStorage(block_.id(), sizeof(off), off, 0);
  allocate(16, 8);
}

bool OpacityShadowMap::allocate(int side, int layers) {
  if (side == side_ && layers == layers_) return true;
  if (side == failedSide_ && layers == failedLayers_) return false;  // said once
  const std::size_t sums = std::size_t(side) * std::size_t(side) * std::size_t(layers);
  gl::Buffer buffer = gl::createBuffer();
  gl::Texture texture = gl::createTexture(GL_TEXTURE_3D);
  glGetError();
  glNamedBufferStorage(buffer.id(), GLsizeiptr(sums * 4), nullptr, 0);
  glTextureStorage3D(texture.id(), 1, GL_R32F, side, side, layers + 1);
  if (glGetError() != GL_NO_ERROR) {
    // A menu or config value the GPU cannot hold: keep the map it has.
    log::error("render.shadow_resolution ", side, ", render.shadow_layers ", layers,
               ": no GPU memory for the shadow map (", sums * 8, " bytes); keeping ", side_, " x ",
               layers_);
    failedSide_ = side;
    failedLayers_ = layers;
    return false;
  }
  layerSums_ = std::move(buffer);
  texture_ = std::move(texture);
  const GLuint zero = 0;
  glClearNamedBufferData(layerSums_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTextureParameteri(texture_.id(), wrap, GL_CLAMP_TO_EDGE);
  const float none = 0.0f;
  glClearTexImage(texture_.id(), 0, GL_RED, GL_FLOAT, &none);
  side_ = side;
  layers_ = layers;
  return true;
}

void OpacityShadowMap::build(const ParticleBackend::Records& records, std::size_t capacity,
                             const RenderSettings& look) {
  const bool on = look.shadows && records.countBuffer != 0;
  if (!on && !blockOn_) return;  // the block already says "none": nothing to do this frame
  const LightFrame light = lightFrame(look.lightDirection);
  if (on) allocate(look.shadowResolution, look.shadowLayers);
  const GLuint groups = GLuint(std::clamp<std::size_t>((capacity + 255) / 256, 1, kMaxGroups));

  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kExtent, extent_.id());
  if (on) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPositionLife, records.positionLife);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVelocityKind, records.velocityKind);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCounts, records.countBuffer);
    bounds_.use();
    glProgramUniform1ui(bounds_.id(), 0, records.countOffset / 4);
    glProgramUniform1ui(bounds_.id(), 1, records.countAdd);
    uniform3(bounds_, 2, light.right);
    uniform3(bounds_, 3, light.up);
    uniform3(bounds_, 4, light.toLight);
    glDispatchCompute(groups, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBlockOut, block_.id());
  frame_.use();
  uniform3(frame_, 2, light.right);
  uniform3(frame_, 3, light.up);
  uniform3(frame_, 4, light.toLight);
  glProgramUniform1f(frame_.id(), 5, look.size);
  glProgramUniform1f(frame_.id(), 6, look.shadowDensity);
  glProgramUniform1i(frame_.id(), 7, side_);
  glProgramUniform1i(frame_.id(), 8, layers_);
  glProgramUniform1i(frame_.id(), 9, on ? 1 : 0);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_UNIFORM_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  blockOn_ = on;
  if (!on) return;

  glBindBufferBase(GL_UNIFORM_BUFFER, kBlockBinding, block_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLayerSums, layerSums_.id());
  splat_.use();
  glProgramUniform1ui(splat_.id(), 0, records.countOffset / 4);
  glProgramUniform1ui(splat_.id(), 1, records.countAdd);
  glProgramUniform2f(splat_.id(), 2, look.opacityBirth, look.opacityDeath);
  const float r = 0.5f * look.size;
  glProgramUniform1f(splat_.id(), 3, std::numbers::pi_v<float> * r * r);
  glProgramUniform1f(splat_.id(), 4, puffCoverage());
  glDispatchCompute(groups, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  accumulate_.use();
  glProgramUniform1i(accumulate_.id(), 0, side_);
  glProgramUniform1i(accumulate_.id(), 1, layers_);
  glBindImageTexture(0, texture_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  glDispatchCompute(GLuint((side_ + 15) / 16), GLuint((side_ + 15) / 16), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

std::vector<float> OpacityShadowMap::transmittance(const std::vector<glm::vec3>& points) const {
  if (points.empty()) return {};
  if (!probe_)
    probe_ = std::make_unique<gl::Program>(std::vector<std::string>{"shadow_probe.comp"});
  std::vector<glm::vec4> padded;
  for (const glm::vec3& p : points)
    padded.emplace_back(p, 1.0f);
  gl::Buffer in = gl::createBuffer(), out = gl::createBuffer();
  glNamedBufferStorage(in.id(), GLsizeiptr(padded.size() * sizeof(glm::vec4)), padded.data(), 0);
  glNamedBufferStorage(out.id(), GLsizeiptr(points.size() * 4), nullptr, GL_CLIENT_STORAGE_BIT);
  handles().bind();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
  probe_->use();
  glProgramUniform1ui(probe_->id(), 0, GLuint(points.size()));
  glDispatchCompute(GLuint((points.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> result(points.size());
  glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(result.size() * 4), result.data());
  return result;
}

}  // namespace sandstorm
