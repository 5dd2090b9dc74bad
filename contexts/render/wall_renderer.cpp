#include "contexts/render/wall_renderer.h"

#include <epoxy/gl.h>

#include "core/cave/wall_views.h"
#include "core/flow/probe.h"
#include "core/movie/movie_compositor.h"
#include "core/tracking/wand_handles.h"

namespace sandstorm {

WallRenderer::WallRenderer(const WallRendererSetup& s)
    : wall_(s.wall),
      near_(s.nearPlane),
      far_(s.farPlane),
      system_(s.initial, ParticleSystem::Options{.capacity = s.capacity,
                                                 .capacityLimit = s.capacityLimit,
                                                 .backend = s.backend,
                                                 .share = s.share,
                                                 .shareReader = s.shareReader,
                                                 .tuning = s.tuning,
                                                 .uploads = s.uploads}),
      anaglyph_(std::vector<std::string>{"fullscreen.vert", "anaglyph.frag"}),
      emptyVao_(gl::createVertexArray()) {
  if (s.terrain) {
    system_.setTerrain(s.terrain);
    viewRenderer_.scene().setTerrain(s.terrain);
  }
}

void WallRenderer::frame(const FramePacket& packet, glm::ivec2 windowSize) {
  timer_.begin(gl::FrameStageTimer::Update);
  system_.advance(packet);
  timer_.end();
  drewOffscreen_ = windowSize.x <= 0 || windowSize.y <= 0;
  if (drewOffscreen_) {
    offscreen_.resize(wall_.offscreenSize);
    drawViews(packet, offscreen_.framebuffer(), wall_.offscreenSize);
  } else {
    drawViews(packet, 0, windowSize);
  }
  lastSize_ = drewOffscreen_ ? wall_.offscreenSize : windowSize;
  timer_.endFrame();
}

void WallRenderer::drawViews(const FramePacket& packet, std::uint32_t destination,
                             glm::ivec2 size) {
  const float aspect = float(size.x) / float(size.y);
  const std::vector<View> views = wallViews(wall_, packet.viewer, aspect, near_, far_);
  std::vector<glm::vec3> handles;
  for (const WandHandle& h : wandHandles(system_.state()))
    handles.push_back(h.position);
  viewRenderer_.scene().setWand(packet.wand, packet.viewer.navigation, std::move(handles));
  viewRenderer_.scene().updateFlow(system_.state(), system_.field(), packet.fieldBlend,
                                   packet.simDt, packet.reset);
  const std::optional<glm::vec3> probe =
      probePoint(system_.state(), packet.wand, packet.viewer.navigation);
  viewRenderer_.scene().setProbe(probe, system_.state().probe.radius);
  const std::vector<glm::ivec4> eyes = eyeViewports(wall_.stereo, size);
  const glm::ivec2 viewSize(eyes[0].z, eyes[0].w);
  renderer_ = system_.state().render.mode == RenderMode::Points ? "points"
              : system_.splats(&views[0], viewSize)             ? "splats"
                                                                : "billboards";
  switch (wall_.stereo) {
    case StereoMode::Mono:
    case StereoMode::LeftEye:
    case StereoMode::RightEye:
      viewRenderer_.render(system_, views[0], size, destination, {0, 0}, &timer_);
      break;
    case StereoMode::SideBySide:
    case StereoMode::TopBottom:
      for (std::size_t eye = 0; eye < 2; ++eye)
        viewRenderer_.render(system_, views[eye], viewSize, destination, {eyes[eye].x, eyes[eye].y},
                             &timer_, eye == 0 ? &views[1] : nullptr);
      break;
    case StereoMode::QuadBuffer:
      glNamedFramebufferDrawBuffer(0, GL_BACK_LEFT);
      viewRenderer_.render(system_, views[0], size, 0, {0, 0}, &timer_, &views[1]);
      glNamedFramebufferDrawBuffer(0, GL_BACK_RIGHT);
      viewRenderer_.render(system_, views[1], size, 0, {0, 0}, &timer_);
      glNamedFramebufferDrawBuffer(0, GL_BACK);
      break;
    case StereoMode::Anaglyph: {
      for (int eye = 0; eye < 2; ++eye) {
        eyes_[eye].resize(size);
        viewRenderer_.render(system_, views[std::size_t(eye)], size, eyes_[eye].framebuffer(),
                             {0, 0}, &timer_, eye == 0 ? &views[1] : nullptr);
      }
      glBindFramebuffer(GL_FRAMEBUFFER, destination);
      glViewport(0, 0, size.x, size.y);
      glBindTextureUnit(0, eyes_[0].colorTexture());
      glBindTextureUnit(1, eyes_[1].colorTexture());
      anaglyph_.use();
      glProgramUniform2i(anaglyph_.id(), 0, 0, 0);
      glBindVertexArray(emptyVao_.id());
      glDrawArrays(GL_TRIANGLES, 0, 3);
      glBindVertexArray(0);
      break;
    }
  }
  measure(packet.frame, probe);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// After the views: the render block (the colour quantity) and the colour
// grids are still bound.
void WallRenderer::measure(std::uint32_t frame, std::optional<glm::vec3> probe) {
  const ParticleState& state = system_.state();
  if (state.render.colorRange != ColorRange::Particles && !state.probe.enabled) return;
  if (!measure_) measure_ = std::make_unique<ParticleMeasure>();
  measure_->measure(
      frame, system_.update().records(), system_.update().capacity(),
      probe ? std::optional<glm::vec4>(glm::vec4(*probe, state.probe.radius)) : std::nullopt);
}

void WallRenderer::drawOverlay(const UiDrawData& overlay, const UiFont& font) {
  if (!ui_) ui_ = std::make_unique<UiRenderer>(font);
  glBindFramebuffer(GL_FRAMEBUFFER, drewOffscreen_ ? offscreen_.framebuffer() : 0);
  // The same place in each eye's image: no disparity, on the wall's plane.
  for (const glm::ivec4& viewport : eyeViewports(wall_.stereo, lastSize_))
    ui_->draw(overlay, viewport);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

Image WallRenderer::capture() const {
  if (drewOffscreen_) return offscreen_.readPixels();
  return readFramebuffer(0, GL_BACK, lastSize_);
}

std::vector<Image> WallRenderer::captureEyes() const {
  if (!drewOffscreen_ && wall_.stereo == StereoMode::QuadBuffer)
    return {readFramebuffer(0, GL_BACK_LEFT, lastSize_),
            readFramebuffer(0, GL_BACK_RIGHT, lastSize_)};
  return splitEyes(capture(), wall_.stereo);
}

}  // namespace sandstorm
