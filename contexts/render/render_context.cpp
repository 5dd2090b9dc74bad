#include "contexts/render/render_context.h"

#include <epoxy/gl.h>

#include <chrono>

#include "contexts/particles/simulation_share.h"
#include "core/util/log.h"

namespace sandstorm {

RenderContext::RenderContext(std::unique_ptr<GlContext> context, WallRendererSetup setup,
                             FrameChannel& channel, int consumer, SwapBarrier& barrier)
    : context_(std::move(context)),
      setup_(std::move(setup)),
      channel_(channel),
      consumer_(consumer),
      barrier_(barrier) {}

RenderContext::~RenderContext() {
  join();
}

void RenderContext::start() {
  thread_ = std::thread([this] { run(); });
}

void RenderContext::join() {
  if (thread_.joinable()) thread_.join();
}

std::optional<std::string> RenderContext::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

std::vector<WallFrameSample> RenderContext::samples() const {
  std::lock_guard lock(mutex_);
  return samples_;
}

WallStats RenderContext::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

void RenderContext::run() {
  try {
    context_->makeCurrent();
    std::unique_ptr<WallRenderer> renderer = std::make_unique<WallRenderer>(setup_);
    log::debug("wall '", name(), "': ", context_->description());
    // Wall-clock time on this thread is for the statistics only; the
    // simulation's time comes from the packets.
    std::optional<std::chrono::steady_clock::time_point> lastSwap;
    auto waiting = std::chrono::steady_clock::now();
    while (std::shared_ptr<const FramePacket> packet = channel_.take(consumer_)) {
      const auto start = std::chrono::steady_clock::now();
      const double packetWait = std::chrono::duration<double, std::milli>(start - waiting).count();
      renderer->frame(*packet, context_->framebufferSize());
      if (overlay_)
        if (const std::shared_ptr<const UiDrawData> menu = overlay_())
          renderer->drawOverlay(*menu, font_);
      if (hook_) hook_(*renderer, *packet);
      renderer->endFrame();
      // Read once a frame: a client-side query, no wait for the GPU.
      std::uint64_t errors = 0;
      for (GLenum e = glGetError(); e != GL_NO_ERROR && errors < 16; e = glGetError()) {
        if (stats_.glErrors + errors == 0)
          log::warn("wall '", name(), "': GL error 0x", std::hex, e, std::dec, " at frame ",
                    packet->frame, " (further ones are counted in the stats)");
        ++errors;
      }
      // A count a frame or two old: waiting for this frame's would drain the GPU every frame.
      const std::size_t live = renderer->particles().update().lateCount();
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count();
      const std::optional<gl::FrameStageTimer::Times> gpu = renderer->stageTimes();
      const auto drawn = std::chrono::steady_clock::now();
      barrier_
          .arrive_and_wait();  // the swap barrier: nobody presents frame f before all have drawn it
      const double barrierWait =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - drawn)
              .count();
      context_->swapBuffers();
      const auto swapped = std::chrono::steady_clock::now();
      waiting = swapped;
      const double interval =
          lastSwap ? std::chrono::duration<double>(swapped - *lastSwap).count() : 0.0;
      lastSwap = swapped;
      std::lock_guard lock(mutex_);
      stats_.capacity = renderer->particles().update().capacity();
      if (gpu) {
        stats_.updateMs = (*gpu)[gl::FrameStageTimer::Update];
        stats_.sceneMs = (*gpu)[gl::FrameStageTimer::Scene];
        stats_.renderMs = (*gpu)[gl::FrameStageTimer::Particles];
        stats_.postMs = (*gpu)[gl::FrameStageTimer::Post];
      }
      if (packet->fieldUpdate) {
        stats_.fieldUploadMs = renderer->particles().update().lastFieldUploadMs();
        ++stats_.fieldUploads;
      }
      stats_.frame = packet->frame;
      stats_.frameMs = ms;
      if (interval > 0.0)
        stats_.fps = stats_.fps > 0.0 ? 0.9 * stats_.fps + 0.1 / interval : 1.0 / interval;
      stats_.liveParticles = live;
      stats_.glErrors += errors;
      renderer_ = renderer->renderer();
      if (packet->frame >= warmup_)
        samples_.push_back({interval * 1e3, ms, barrierWait, packetWait, gpu, live});
    }
    renderer.reset();  // GL objects go with their own context current
    context_->releaseCurrent();
  } catch (const std::exception& e) {
    {
      std::lock_guard lock(mutex_);
      error_ = "wall '" + name() + "': " + e.what();
    }
    log::error(*error_);
    barrier_.arrive_and_drop();
    channel_.leave(consumer_);
    if (setup_.share)
      setup_.share->abandon();  // walls drawing a shared simulation must not wait for it
    try {
      context_->releaseCurrent();
    } catch (...) {
    }
  }
  finished_ = true;
}

}  // namespace sandstorm
