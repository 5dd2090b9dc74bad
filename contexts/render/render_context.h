// RenderContext: one GL context and the thread that draws with it. It draws
// one wall or several (RenderWall): a window's wall alone, or every offscreen
// wall of one GPU together, because contexts on one GPU take turns on it and
// a frame then costs far more than its work (docs/PERFORMANCE.md measured
// 17 ms for eight views of 10^5 particles in four contexts, 6 ms in one).
// Per frame it takes the main context's packet, draws each of its walls in
// order, waits at the swap barrier with every other context, then presents,
// so all walls show the same frame and a slow wall slows them all. GL objects
// are made and released on this thread, with its context current.
//
// A context may come with a second one of its share group: an UploadThread
// then copies its walls' coming series steps to the GPU beside their work.
//
// A window's wall that opens before its first packet (the field still being
// read) shows the read's progress meanwhile: a bar in each eye's view, drawn
// with clears (contexts/ui/progress_bar.h), so a CAVE's walls show what they
// wait for.
//
// A wall that fails (a lost context, a shader error) records the error on
// each of the context's walls, the context drops out of the barrier and leaves
// the channel, so the others never hang; the app sees error() and shuts
// everything down.
#pragma once

#include <atomic>
#include <barrier>
#include <memory>
#include <thread>
#include <vector>

#include "contexts/gl/upload_thread.h"
#include "contexts/platform/gl_context.h"
#include "contexts/render/render_wall.h"
#include "core/sim/frame_channel.h"

namespace sandstorm {

class RenderContext {
 public:
  using SwapBarrier = std::barrier<>;

  // `walls`: drawn in this order (a shared simulation's owner first); they
  // must outlive this. Each wall counts once in `barrier`. `uploadContext`:
  // shares objects with `context` (null: the walls upload on this thread).
  RenderContext(std::unique_ptr<GlContext> context, std::vector<RenderWall*> walls,
                FrameChannel& channel, SwapBarrier& barrier,
                std::unique_ptr<GlContext> uploadContext = nullptr);
  ~RenderContext();
  RenderContext(const RenderContext&) = delete;
  RenderContext& operator=(const RenderContext&) = delete;

  // Another wall for this context, drawn after the others (before start()).
  void addWall(RenderWall* wall) { walls_.push_back(wall); }
  void start();
  void join();
  GlContext& glContext() { return *context_; }
  const std::vector<RenderWall*>& walls() const { return walls_; }
  bool finished() const { return finished_; }

 private:
  void run();
  // Until the first packet is there: the progress of the work on the board
  // (ProgressBoard) in a window, nothing offscreen; and the field packet 0
  // is to carry uploaded as soon as it is offered (FrameChannel::offerField).
  void waitForFirstPacket();
  // Uploads the offered field into each wall that has not taken it; whether any did.
  bool uploadOfferedField();

  std::unique_ptr<GlContext> context_;
  std::unique_ptr<UploadThread> uploads_;  // ends after the walls' thread
  std::vector<RenderWall*> walls_;
  FrameChannel& channel_;
  SwapBarrier& barrier_;
  std::thread thread_;
  std::atomic<bool> finished_{false};
};

}  // namespace sandstorm
