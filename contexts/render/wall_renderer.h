// WallRenderer: everything one wall draws with, on the wall's own GL context:
// its copy of the particle system, the scene, and the stereo layout. Each
// frame it applies the packet, simulates, and renders every eye's view into
// the wall's framebuffer (the window's, or an offscreen image).
#pragma once

#include <memory>
#include <optional>

#include "contexts/gl/frame_stage_timer.h"
#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/particles/particle_measure.h"
#include "contexts/particles/particle_system.h"
#include "contexts/render/view_renderer.h"
#include "contexts/render/view_targets.h"
#include "contexts/ui/ui_renderer.h"
#include "core/config/app_config.h"
#include "core/util/image.h"

namespace sandstorm {

struct WallRendererSetup {
  WallSpec wall;
  ParticleState initial;
  std::shared_ptr<const HeightMap> terrain;
  std::size_t capacity = 1u << 20;
  std::size_t capacityLimit = 1u << 26;
  std::string backend = "compute";
  std::shared_ptr<SimulationShare> share;  // one simulation per GPU (ParticleSystem::Options)
  int shareReader = -1;
  GpuTuning tuning;
  float nearPlane = 0.05f;
  float farPlane = 500.0f;
  UploadThread* uploads = nullptr;  // the context's upload thread, if it has one (RenderContext)
};

class WallRenderer {
 public:
  explicit WallRenderer(const WallRendererSetup& setup);

  // Applies the packet, advances the particles and draws the wall. `windowSize`
  // is the default framebuffer's size; (0, 0) draws into the offscreen image.
  void frame(const FramePacket& packet, glm::ivec2 windowSize);
  // Before packet 0: its field uploaded (ParticleSystem::uploadFieldAhead).
  void uploadFieldAhead(const FieldUpdate& field) { system_.uploadFieldAhead(field); }
  // The frame is done with the particles (after captures and hash probes).
  void endFrame() { system_.endFrame(); }
  // Draws an overlay (the menu, the legend) over the wall's last frame: laid
  // out for one eye's image and drawn into each (eyeViewports), so that a
  // stereo wall shows it to both eyes at the same place, on the wall's plane.
  void drawOverlay(const UiDrawData& overlay, const UiFont& font);
  // The image last drawn (offscreen) or the back buffer (window).
  Image capture() const;
  // Each eye's image of the last frame: the halves of a side-by-side or
  // top-bottom image, a quad-buffered window's left and right back buffers;
  // one image for the modes that draw one picture.
  std::vector<Image> captureEyes() const;

  // GPU milliseconds of this wall's stages in a recent frame (a few frames old).
  const std::optional<gl::FrameStageTimer::Times>& stageTimes() const { return timer_.latest(); }
  // The newest finished measurement of the particles (render.color_range =
  // particles, probe.enabled), if any; never waits.
  std::optional<ParticleMeasurement> measurement() {
    return measure_ ? measure_->latest() : std::nullopt;
  }
  // The particle renderer the last view used: "splats" or "billboards" (or "points").
  const char* renderer() const { return renderer_; }

  const ParticleSystem& particles() const { return system_; }
  ParticleSystem& particles() { return system_; }
  const WallSpec& wall() const { return wall_; }

 private:
  void drawViews(const FramePacket& packet, std::uint32_t destination, glm::ivec2 size);

  WallSpec wall_;
  float near_, far_;
  ParticleSystem system_;
  ViewRenderer viewRenderer_;
  OutputTarget offscreen_;
  OutputTarget eyes_[2];  // anaglyph: each eye's image before they are combined
  gl::Program anaglyph_;
  gl::VertexArray emptyVao_;
  std::unique_ptr<UiRenderer> ui_;
  glm::ivec2 lastSize_{0};
  // `probe`: this frame's probe point (probePoint), if any.
  void measure(std::uint32_t frame, std::optional<glm::vec3> probe);

  gl::FrameStageTimer timer_;
  std::unique_ptr<ParticleMeasure> measure_;  // made when first asked for
  const char* renderer_ = "billboards";
  bool drewOffscreen_ = false;
};

}  // namespace sandstorm
