// ViewTargets: the offscreen buffers one view renders through, all the view's
// size: the scene (colour; the raster items' depth buffer; and the scene's
// depth, which SceneBackground writes and particles test against) and the
// particle accumulation buffer (premultiplied colour + premultiplied normals,
// both RGBA16F, and the premultiplied share of the light that reaches the
// particles through the dust, R16F) that ParticlePost lights and composites.
#pragma once

#include <glm/glm.hpp>

#include "contexts/gl/objects.h"

namespace sandstorm {

class ViewTargets {
 public:
  // (Re)allocates when the size changes.
  void resize(glm::ivec2 size);
  glm::ivec2 size() const { return size_; }

  std::uint32_t sceneFramebuffer() const { return sceneFbo_.id(); }
  std::uint32_t particleFramebuffer() const { return particleFbo_.id(); }
  std::uint32_t sceneColor() const { return sceneColor_.id(); }
  // Window depth (R32F, 1 at the far plane) of the nearest scene surface.
  std::uint32_t sceneDepth() const { return sceneDepth_.id(); }
  // The scene framebuffer's depth buffer: the raster items only.
  std::uint32_t itemsDepth() const { return itemsDepth_.id(); }
  std::uint32_t particleColor() const { return particleColor_.id(); }
  std::uint32_t particleNormal() const { return particleNormal_.id(); }
  std::uint32_t particleLight() const { return particleLight_.id(); }

 private:
  glm::ivec2 size_{0};
  gl::Framebuffer sceneFbo_, particleFbo_;
  gl::Texture sceneColor_, sceneDepth_, itemsDepth_, particleColor_, particleNormal_,
      particleLight_;
};

// OutputTarget: an RGBA8 colour texture + depth framebuffer: an offscreen
// wall's image, or one eye's image before stereo composition. Its pixels can
// be read back as an Image.
class OutputTarget {
 public:
  void resize(glm::ivec2 size);
  glm::ivec2 size() const { return size_; }
  std::uint32_t framebuffer() const { return fbo_.id(); }
  std::uint32_t colorTexture() const { return color_.id(); }
  struct Image readPixels() const;

 private:
  glm::ivec2 size_{0};
  gl::Framebuffer fbo_;
  gl::Texture color_;
  gl::Renderbuffer depth_;
};

// Reads the bound framebuffer's colour buffer `buffer` (GL_BACK, GL_COLOR_ATTACHMENT0...).
struct Image readFramebuffer(std::uint32_t framebuffer, std::uint32_t buffer, glm::ivec2 size);

}  // namespace sandstorm
