// RenderWall: one wall as a RenderContext draws it: its WallRenderer (made and
// released on the context's thread), the hooks and the menu drawn over it, and
// its statistics, which other threads read. The app keeps one per wall; the
// RenderContext whose GL context the wall lives in draws it each frame.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "contexts/render/wall_renderer.h"
#include "core/sim/frame_packet.h"
#include "core/util/reservoir.h"

namespace sandstorm {

struct WallStats {
  std::uint32_t frame = 0;
  double frameMs = 0.0;  // CPU time of this wall's part of the last frame
  double fps = 0.0;      // smoothed
  std::size_t liveParticles = 0;
  std::size_t liveMolecules = 0;  // a frame or two old, like the particles'
  std::size_t capacity = 0;
  // GPU time per stage, all views of a frame (a few frames old); render: the particles.
  double updateMs = 0.0, sceneMs = 0.0, renderMs = 0.0, postMs = 0.0;
  double fieldUploadMs = 0.0;       // CPU time of the last field upload to this wall's GPU
  double fieldUploadTotalMs = 0.0;  // the same, summed over every upload
  int fieldUploads = 0;             // how many field grids this wall has received
  std::uint64_t glErrors = 0;  // GL errors raised by this wall's frames (glGetError once a frame)
  // The newest measurement of its particles (probe count, colour range), if asked for.
  std::optional<ParticleMeasurement> measure;
};

// One frame of one wall, as measured on its thread: what the run statistics
// (app/run_stats.h) are made of.
struct WallFrameSample {
  double intervalMs = 0.0;                        // present to present
  double cpuMs = 0.0;                             // this wall's part of its thread's work
  double waitMs = 0.0;                            // at the swap barrier, for the other walls
  double packetWaitMs = 0.0;                      // for the main context's packet
  std::optional<gl::FrameStageTimer::Times> gpu;  // a few frames old
  std::size_t live = 0;
};

class RenderWall {
 public:
  // Called on the drawing thread after each frame of this wall is drawn,
  // before the swap barrier: screenshots, particle dumps, test probes.
  using FrameHook = std::function<void(WallRenderer&, const FramePacket&)>;
  // What to draw over this wall each frame, the menu or the legend (latest wins); null: nothing.
  using OverlaySource = std::function<std::shared_ptr<const UiDrawData>()>;

  // `consumer`: this wall's place in the FrameChannel.
  RenderWall(WallRendererSetup setup, int consumer);
  ~RenderWall();
  RenderWall(const RenderWall&) = delete;
  RenderWall& operator=(const RenderWall&) = delete;

  // Before the drawing thread starts.
  void setFrameHook(FrameHook hook) { hook_ = std::move(hook); }
  // Called with the wall's picture (the views and the legend) before the menu
  // is drawn over it, or after it with `withMenu`: what a movie records.
  void setPictureHook(FrameHook hook, bool withMenu) {
    pictureHook_ = std::move(hook);
    pictureWithMenu_ = withMenu;
  }
  // Overlays, each laid out for one eye's image and drawn into each eye's (a
  // stereo wall shows it to both eyes, on the wall's plane): the picture's
  // (the legend) first, then the menu's on top; they share one font atlas
  // (Dear ImGui's default), the first one's.
  enum class Layer { Picture, Menu };
  void addOverlay(OverlaySource source, UiFont font, Layer layer) {
    overlays_.push_back({std::move(source), layer});
    if (font_.rgba.empty()) font_ = std::move(font);
  }
  // Every frame from `warmup` on (after the thread ends: the whole run); past
  // kMaxSamples frames, a uniform sample of them (bounded memory in long runs).
  static constexpr std::size_t kMaxSamples = 65536;
  void sampleFrom(std::uint32_t warmup) { warmup_ = warmup; }

  const std::string& name() const { return setup_.wall.name; }
  int consumer() const { return consumer_; }
  const WallRendererSetup& setup() const { return setup_; }
  std::optional<std::string> error() const;
  WallStats stats() const;
  std::vector<WallFrameSample> samples() const;
  std::size_t measuredFrames() const;
  const char* renderer() const;

  // The drawing thread's side (RenderContext), with the wall's GL context current.
  struct Drawn {
    double cpuMs = 0.0;
    std::uint64_t glErrors = 0;
    std::size_t live = 0, molecules = 0;
    std::optional<gl::FrameStageTimer::Times> gpu;
    std::optional<ParticleMeasurement> measure;
  };
  // Makes the wall's renderer; `uploads`: the context's upload thread, or null.
  void open(UploadThread* uploads = nullptr);
  Drawn draw(const FramePacket& packet, glm::ivec2 framebufferSize);
  // Before packet 0: the field it is to carry, uploaded (FrameChannel::offerField).
  void uploadFieldAhead(const FieldUpdate& field);
  void record(const FramePacket& packet, const Drawn& drawn, double intervalMs, double waitMs,
              double packetWaitMs);
  void fail(const std::string& message);
  void close();

 private:
  WallRendererSetup setup_;
  int consumer_;
  FrameHook hook_, pictureHook_;
  bool pictureWithMenu_ = false;
  struct Overlay {
    OverlaySource source;
    Layer layer;
  };
  void drawOverlays(Layer layer);
  std::vector<Overlay> overlays_;
  UiFont font_;
  std::unique_ptr<WallRenderer> renderer_;  // on the drawing thread only
  mutable std::mutex mutex_;
  std::optional<std::string> error_;
  WallStats stats_;
  std::uint32_t warmup_ = 0xffffffffu;  // no samples unless asked
  Reservoir<WallFrameSample> samples_{kMaxSamples};
  const char* rendererName_ = "";
};

}  // namespace sandstorm
