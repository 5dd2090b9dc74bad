#include "contexts/render/render_context.h"

#include <chrono>

#include "core/util/log.h"

namespace sandstorm {

RenderContext::RenderContext(std::unique_ptr<GlContext> context, WallRendererSetup setup, FrameChannel& channel,
                             int consumer, SwapBarrier& barrier)
    : context_(std::move(context)), setup_(std::move(setup)), channel_(channel), consumer_(consumer),
      barrier_(barrier) {}

RenderContext::~RenderContext() { join(); }

void RenderContext::start() { thread_ = std::thread([this] { run(); }); }

void RenderContext::join() {
  if (thread_.joinable()) thread_.join();
}

std::optional<std::string> RenderContext::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

WallStats RenderContext::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

void RenderContext::run() {
  bool inBarrier = true;
  try {
    context_->makeCurrent();
    std::unique_ptr<WallRenderer> renderer = std::make_unique<WallRenderer>(setup_);
    log::debug("wall '", name(), "': ", context_->description());
    while (std::shared_ptr<const FramePacket> packet = channel_.take(consumer_)) {
      const auto start = std::chrono::steady_clock::now();
      renderer->frame(*packet, context_->framebufferSize());
      if (hook_) hook_(*renderer, *packet);
      const std::size_t live = countParticles_ ? renderer->particles().update().liveCount() : 0;
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      barrier_.arrive_and_wait();  // the swap barrier: nobody presents frame f before all have drawn it
      context_->swapBuffers();
      std::lock_guard lock(mutex_);
      stats_.frame = packet->frame;
      stats_.frameMs = ms;
      stats_.fps = packet->dt > 0.0f ? 0.9 * stats_.fps + 0.1 / double(packet->dt) : stats_.fps;
      stats_.liveParticles = live;
    }
    renderer.reset();  // GL objects go with their own context current
    context_->releaseCurrent();
  } catch (const std::exception& e) {
    {
      std::lock_guard lock(mutex_);
      error_ = "wall '" + name() + "': " + e.what();
    }
    log::error(*error_);
    if (inBarrier) barrier_.arrive_and_drop();
    inBarrier = false;
    channel_.leave(consumer_);
    try {
      context_->releaseCurrent();
    } catch (...) {
    }
  }
  finished_ = true;
}

}  // namespace sandstorm
