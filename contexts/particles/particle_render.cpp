#include "contexts/particles/particle_render.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "contexts/particles/particle_backend.h"
#include "contexts/particles/particle_sort.h"
#include "contexts/render/view_targets.h"
#include "core/light/puff_sprite.h"

namespace sandstorm {
namespace {

// The puff (core/light/puff_sprite.h) as an R8 texture.
gl::Texture makeSprite() {
  constexpr int kSize = kPuffSize;
  const std::vector<std::uint8_t> pixels = puffSpritePixels();
  gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, GL_R8, kSize, kSize);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(t.id(), 0, 0, 0, kSize, kSize, GL_RED, GL_UNSIGNED_BYTE, pixels.data());
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

}  // namespace

ParticleRender::ParticleRender()
    : billboards_(std::vector<std::string>{"particle_render.vert", "particle_render.geom",
                                           "particle_render.frag"}),
      points_(std::vector<std::string>{"particle_render.vert", "particle_render.frag"},
              std::vector<std::string>{"POINTS"}),
      sprite_(makeSprite()),
      empty_(gl::createVertexArray()) {}

ParticleRender::~ParticleRender() = default;

void ParticleRender::draw(const ParticleBackend& particles, const ViewTargets& targets,
                          RenderMode mode, RenderOrder order) const {
  glBindFramebuffer(GL_FRAMEBUFFER, targets.particleFramebuffer());
  glViewport(0, 0, targets.size().x, targets.size().y);
  const float clear[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(targets.particleFramebuffer(), GL_COLOR, 0, clear);
  glClearNamedFramebufferfv(targets.particleFramebuffer(), GL_COLOR, 1, clear);
  glClearNamedFramebufferfv(targets.particleFramebuffer(), GL_COLOR, 2, clear);

  glDisable(GL_DEPTH_TEST);  // the fragment stage tests against the scene's depth itself
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glBindTextureUnit(2, sprite_.id());
  glBindTextureUnit(3, targets.sceneDepth());
  if (mode == RenderMode::Points) {
    glEnable(GL_PROGRAM_POINT_SIZE);
    points_.use();
  } else if (order == RenderOrder::Sorted && particles.records().countBuffer != 0) {
    const ParticleBackend::Records r = particles.records();
    if (!sort_) {
      sort_ = std::make_unique<ParticleSort>();
      sortedBillboards_ = std::make_unique<gl::Program>(
          std::vector<std::string>{"particle_render.vert", "particle_render.geom",
                                   "particle_render.frag"},
          std::vector<std::string>{"SORTED"});
    }
    sort_->sort(r, particles.capacity());
    sortedBillboards_->use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, r.positionLife);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, r.velocityKind);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, sort_->indices());
    glBindVertexArray(empty_.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, sort_->command());
    glDrawArraysIndirect(GL_POINTS, nullptr);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    return;
  } else {
    billboards_.use();
  }
  particles.draw();
  glDisable(GL_BLEND);
  glDisable(GL_PROGRAM_POINT_SIZE);
}

}  // namespace sandstorm
