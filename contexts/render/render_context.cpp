#include "contexts/render/render_context.h"

#include <chrono>
#include <optional>

#include <epoxy/gl.h>

#include "contexts/particles/simulation_share.h"
#include "contexts/ui/progress_bar.h"
#include "core/cave/wall_views.h"
#include "core/util/error.h"
#include "core/util/log.h"
#include "core/util/progress_board.h"

namespace sandstorm {

RenderContext::RenderContext(std::unique_ptr<GlContext> context, std::vector<RenderWall*> walls,
                             FrameChannel& channel, SwapBarrier& barrier,
                             std::unique_ptr<GlContext> uploadContext)
    : context_(std::move(context)), walls_(std::move(walls)), channel_(channel), barrier_(barrier) {
  if (walls_.empty()) throw Error("RenderContext: no wall to draw");
  if (uploadContext) uploads_ = std::make_unique<UploadThread>(std::move(uploadContext));
}

RenderContext::~RenderContext() {
  join();
}

void RenderContext::start() {
  thread_ = std::thread([this] { run(); });
}

void RenderContext::join() {
  if (thread_.joinable()) thread_.join();
}

void RenderContext::run() {
  using Clock = std::chrono::steady_clock;
  const auto ms = [](Clock::duration d) {
    return std::chrono::duration<double, std::milli>(d).count();
  };
  const auto arrivals = std::ptrdiff_t(walls_.size());
  try {
    context_->makeCurrent();
    for (RenderWall* wall : walls_)
      wall->open(uploads_.get());
    log::debug("context of wall '", walls_.front()->name(), "': ", context_->description());
    waitForFirstPacket();
    // Wall-clock time on this thread is for the statistics only; the
    // simulation's time comes from the packets.
    std::optional<Clock::time_point> lastSwap;
    auto waiting = Clock::now();
    std::vector<RenderWall::Drawn> drawn(walls_.size());
    for (;;) {
      // Every wall takes the same packet (the first take waits for it).
      std::shared_ptr<const FramePacket> packet;
      for (RenderWall* wall : walls_)
        packet = channel_.take(wall->consumer());
      if (!packet) break;
      const double packetWait = ms(Clock::now() - waiting);
      for (std::size_t i = 0; i < walls_.size(); ++i)
        drawn[i] = walls_[i]->draw(*packet, context_->framebufferSize());
      const auto done = Clock::now();
      // The swap barrier: nobody presents frame f before all have drawn it.
      barrier_.wait(barrier_.arrive(arrivals));
      const double barrierWait = ms(Clock::now() - done);
      context_->swapBuffers();
      const auto swapped = Clock::now();
      waiting = swapped;
      const double interval = lastSwap ? ms(swapped - *lastSwap) : 0.0;
      lastSwap = swapped;
      for (std::size_t i = 0; i < walls_.size(); ++i)
        walls_[i]->record(*packet, drawn[i], interval, barrierWait, packetWait);
    }
    for (RenderWall* wall : walls_)
      wall->close();
    context_->releaseCurrent();
  } catch (const std::exception& e) {
    for (RenderWall* wall : walls_)
      wall->fail("wall '" + wall->name() + "': " + e.what());
    log::error(*walls_.front()->error());
    for (std::ptrdiff_t i = 0; i < arrivals; ++i)
      barrier_.arrive_and_drop();
    for (RenderWall* wall : walls_) {
      channel_.leave(wall->consumer());
      // Walls drawing a shared simulation must not wait for it.
      if (wall->setup().share) wall->setup().share->abandon();
    }
    try {
      for (RenderWall* wall : walls_)
        wall->close();
      context_->releaseCurrent();
    } catch (...) {
    }
  }
  finished_ = true;
}

bool RenderContext::uploadOfferedField() {
  bool any = false;
  for (RenderWall* wall : walls_)
    if (const std::shared_ptr<const FieldUpdate> field =
            channel_.takeOfferedField(wall->consumer())) {
      wall->uploadFieldAhead(*field);
      any = true;
    }
  return any;
}

void RenderContext::waitForFirstPacket() {
  const glm::ivec2 size = context_->framebufferSize();
  const bool window = size.x > 0 && size.y > 0;
  const RenderWall& wall = *walls_.front();  // a window draws one wall
  std::optional<double> shown;               // between two pieces of work the last share stays up
  for (;;) {
    const bool ready = channel_.waitFor(wall.consumer(), std::chrono::milliseconds(50));
    if (uploadOfferedField()) continue;
    if (ready) break;
    if (!window) continue;
    if (const std::optional<ProgressSnapshot> work = ProgressBoard::instance().snapshot())
      shown = work->fraction();
    if (!shown) continue;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDrawBuffer(GL_BACK);  // both of a quad-buffered window's back buffers
    for (const glm::ivec4& eye : eyeViewports(wall.setup().wall.stereo, size))
      drawProgressBar(eye, centredBar(eye, 0.6f), *shown);
    context_->swapBuffers();
  }
  if (shown)
    log::debug("wall '", wall.name(), "' showed the loading's progress until its first frame");
}

}  // namespace sandstorm
