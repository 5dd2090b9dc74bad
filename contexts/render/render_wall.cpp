#include "contexts/render/render_wall.h"

#include <epoxy/gl.h>

#include <chrono>

#include "core/util/log.h"

namespace sandstorm {

RenderWall::RenderWall(WallRendererSetup setup, int consumer)
    : setup_(std::move(setup)), consumer_(consumer) {}

RenderWall::~RenderWall() = default;

std::optional<std::string> RenderWall::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

WallStats RenderWall::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

std::vector<WallFrameSample> RenderWall::samples() const {
  std::lock_guard lock(mutex_);
  return samples_.values();
}

std::size_t RenderWall::measuredFrames() const {
  std::lock_guard lock(mutex_);
  return std::size_t(samples_.seen());
}

const char* RenderWall::renderer() const {
  std::lock_guard lock(mutex_);
  return rendererName_;
}

void RenderWall::open(UploadThread* uploads) {
  setup_.uploads = uploads;
  renderer_ = std::make_unique<WallRenderer>(setup_);
}

void RenderWall::uploadFieldAhead(const FieldUpdate& field) {
  const auto start = std::chrono::steady_clock::now();
  renderer_->uploadFieldAhead(field);
  log::debug(
      "wall '", name(), "': the field uploaded ahead of packet 0 in ",
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(),
      " ms");
}

RenderWall::Drawn RenderWall::draw(const FramePacket& packet, glm::ivec2 framebufferSize) {
  const auto start = std::chrono::steady_clock::now();
  renderer_->frame(packet, framebufferSize);
  drawOverlays(Layer::Picture);
  if (pictureHook_ && !pictureWithMenu_) pictureHook_(*renderer_, packet);
  drawOverlays(Layer::Menu);
  if (pictureHook_ && pictureWithMenu_) pictureHook_(*renderer_, packet);
  if (hook_) hook_(*renderer_, packet);
  renderer_->endFrame();
  Drawn d;
  // Read once a frame: a client-side query, no wait for the GPU.
  for (GLenum e = glGetError(); e != GL_NO_ERROR && d.glErrors < 16; e = glGetError()) {
    if (stats().glErrors + d.glErrors == 0)
      log::warn("wall '", name(), "': GL error 0x", std::hex, e, std::dec, " at frame ",
                packet.frame, " (further ones are counted in the stats)");
    ++d.glErrors;
  }
  // A count a frame or two old: waiting for this frame's would drain the GPU every frame.
  d.live = renderer_->particles().update().lateCount();
  d.molecules = renderer_->particles().molecules().lateCount;
  d.gpu = renderer_->stageTimes();
  d.measure = renderer_->measurement();
  d.cpuMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return d;
}

void RenderWall::drawOverlays(Layer layer) {
  for (const Overlay& overlay : overlays_)
    if (overlay.layer == layer)
      if (const std::shared_ptr<const UiDrawData> data = overlay.source())
        renderer_->drawOverlay(*data, font_);
}

void RenderWall::record(const FramePacket& packet, const Drawn& drawn, double intervalMs,
                        double waitMs, double packetWaitMs) {
  std::lock_guard lock(mutex_);
  stats_.capacity = renderer_->particles().update().capacity();
  if (drawn.gpu) {
    stats_.updateMs = (*drawn.gpu)[gl::FrameStageTimer::Update];
    stats_.sceneMs = (*drawn.gpu)[gl::FrameStageTimer::Scene];
    stats_.renderMs = (*drawn.gpu)[gl::FrameStageTimer::Particles];
    stats_.postMs = (*drawn.gpu)[gl::FrameStageTimer::Post];
  }
  if (packet.fieldUpdate) {
    stats_.fieldUploadMs = renderer_->particles().update().lastFieldUploadMs();
    stats_.fieldUploadTotalMs += stats_.fieldUploadMs;
    ++stats_.fieldUploads;
  }
  stats_.frame = packet.frame;
  stats_.frameMs = drawn.cpuMs;
  if (intervalMs > 0.0)
    stats_.fps = stats_.fps > 0.0 ? 0.9 * stats_.fps + 100.0 / intervalMs : 1e3 / intervalMs;
  stats_.liveParticles = drawn.live;
  stats_.liveMolecules = drawn.molecules;
  if (drawn.measure) stats_.measure = drawn.measure;
  stats_.glErrors += drawn.glErrors;
  rendererName_ = renderer_->renderer();
  if (packet.frame >= warmup_)
    samples_.offer({intervalMs, drawn.cpuMs, waitMs, packetWaitMs, drawn.gpu, drawn.live});
}

void RenderWall::fail(const std::string& message) {
  std::lock_guard lock(mutex_);
  if (!error_) error_ = message;
}

void RenderWall::close() {
  renderer_.reset();  // GL objects go with their own context current
}

}  // namespace sandstorm
