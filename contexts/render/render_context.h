// RenderContext: one wall's thread. It owns the wall's GL context and, on that
// thread, its WallRenderer. Per frame it takes the main context's packet,
// simulates and draws, waits at the swap barrier with every other wall, then
// presents, so all walls show the same frame and a slow wall slows them all.
// GL objects are made and released on this thread, with its context current.
//
// A wall that fails (a lost context, a shader error) records the error, drops
// out of the barrier and leaves the channel, so the others never hang; the app
// sees error() and shuts everything down.
#pragma once

#include <atomic>
#include <barrier>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "contexts/platform/gl_context.h"
#include "contexts/render/wall_renderer.h"
#include "core/sim/frame_channel.h"

namespace sandstorm {

struct WallStats {
  std::uint32_t frame = 0;
  double frameMs = 0.0;  // CPU time of the last frame on this wall's thread
  double fps = 0.0;      // smoothed
  std::size_t liveParticles = 0;
  std::size_t capacity = 0;
  // GPU time per stage, all views of a frame (a few frames old); render: the particles.
  double updateMs = 0.0, sceneMs = 0.0, renderMs = 0.0, postMs = 0.0;
  double fieldUploadMs = 0.0;  // CPU time of the last field upload to this wall's GPU
  int fieldUploads = 0;        // how many field grids this wall has received
  std::uint64_t glErrors = 0;  // GL errors raised by this wall's frames (glGetError once a frame)
};

// One frame of one wall, as measured on its thread: what the run statistics
// (app/run_stats.h) are made of.
struct WallFrameSample {
  double intervalMs = 0.0;                        // present to present
  double cpuMs = 0.0;                             // this thread's work on the frame
  double waitMs = 0.0;                            // at the swap barrier, for the other walls
  double packetWaitMs = 0.0;                      // for the main context's packet
  std::optional<gl::FrameStageTimer::Times> gpu;  // a few frames old
  std::size_t live = 0;
};

class RenderContext {
 public:
  using SwapBarrier = std::barrier<>;
  // Called on the wall's thread after each frame is drawn, before the swap
  // barrier: screenshots, particle dumps, test probes.
  using FrameHook = std::function<void(WallRenderer&, const FramePacket&)>;

  RenderContext(std::unique_ptr<GlContext> context, WallRendererSetup setup, FrameChannel& channel,
                int consumer, SwapBarrier& barrier);
  ~RenderContext();
  RenderContext(const RenderContext&) = delete;
  RenderContext& operator=(const RenderContext&) = delete;

  void setFrameHook(FrameHook hook) { hook_ = std::move(hook); }
  // The menu to draw over this wall each frame (latest wins); null: none.
  using OverlaySource = std::function<std::shared_ptr<const UiDrawData>()>;
  void setOverlay(OverlaySource source, UiFont font) {
    overlay_ = std::move(source);
    font_ = std::move(font);
  }
  void start();
  void join();

  const std::string& name() const { return setup_.wall.name; }
  GlContext& glContext() { return *context_; }
  std::optional<std::string> error() const;
  WallStats stats() const;
  // Every frame from `warmup` on (after join(): the whole run).
  void sampleFrom(std::uint32_t warmup) { warmup_ = warmup; }
  std::vector<WallFrameSample> samples() const;
  const char* renderer() const { return renderer_; }
  bool finished() const { return finished_; }

 private:
  void run();

  std::unique_ptr<GlContext> context_;
  WallRendererSetup setup_;
  FrameChannel& channel_;
  int consumer_;
  SwapBarrier& barrier_;
  FrameHook hook_;
  OverlaySource overlay_;
  UiFont font_;
  std::thread thread_;
  std::atomic<bool> finished_{false};
  mutable std::mutex mutex_;
  std::optional<std::string> error_;
  WallStats stats_;
  std::uint32_t warmup_ = 0xffffffffu;  // no samples unless asked
  std::vector<WallFrameSample> samples_;
  const char* renderer_ = "";
};

}  // namespace sandstorm
