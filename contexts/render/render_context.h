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
  double updateMs = 0.0, renderMs = 0.0, postMs = 0.0;  // GPU time per stage (a few frames old)
  double fieldUploadMs = 0.0;  // CPU time of the last field upload to this wall's GPU
  int fieldUploads = 0;        // how many field grids this wall has received
  std::uint64_t glErrors = 0;  // GL errors raised by this wall's frames (glGetError once a frame)
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
  // Whether the live particle count is read back each frame for stats (a GPU wait).
  void setCountParticles(bool on) { countParticles_ = on; }
  void start();
  void join();

  const std::string& name() const { return setup_.wall.name; }
  GlContext& glContext() { return *context_; }
  std::optional<std::string> error() const;
  WallStats stats() const;
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
  bool countParticles_ = true;
  std::thread thread_;
  std::atomic<bool> finished_{false};
  mutable std::mutex mutex_;
  std::optional<std::string> error_;
  WallStats stats_;
};

}  // namespace sandstorm
