// RunStats: what a run measured, from every wall's per-frame samples after
// the warm-up (run.stats_warmup frames): frames measured, the median and
// 95th-percentile frame time, and per wall the median GPU time of each stage
// (update, scene, particles, post; every view of the frame together), the
// median wait at the swap barrier and for the main context's packet, the
// live particles at the end and the renderer the wall drew with; for a
// series streamed from disk, the steps it played a second of wall time. Printed at
// the end of every run; --stats FILE writes it as JSON.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/playback_meter.h"
#include "contexts/render/render_wall.h"

namespace sandstorm {

struct WallRunStats {
  std::string name;
  std::string renderer;
  std::size_t frames = 0;
  double frameMs = 0.0, frameP95Ms = 0.0;  // present to present
  double cpuMs = 0.0;                      // this wall's thread, its own work
  double updateMs = 0.0, sceneMs = 0.0, particlesMs = 0.0, postMs = 0.0;  // GPU, medians
  double gpuMs = 0.0;  // median of their per-frame sum
  double barrierWaitMs = 0.0, packetWaitMs = 0.0;
  std::size_t live = 0;
};

// The tracker's datagrams over the run, where one was listened to.
struct TrackingRunStats {
  std::uint64_t received = 0, dropped = 0;
  std::uint64_t foreign = 0;  // from hosts not in tracking.sender
};

struct RunStats {
  std::size_t warmup = 0;
  std::size_t frames = 0;  // measured: the first wall's frames after the warm-up
  double frameMs = 0.0, frameP95Ms = 0.0, fps = 0.0;
  std::vector<WallRunStats> walls;
  std::optional<TrackingRunStats> tracking;
  std::optional<PlaybackRunStats> playback;  // a series streamed from disk
};

// `samples`: every measured frame, or a uniform sample of them in a long run
// (RenderWall keeps at most 65536); `frames`: how many were measured; `live`:
// the particles at the end.
WallRunStats summarize(const std::string& name, const std::string& renderer,
                       const std::vector<WallFrameSample>& samples, std::size_t frames,
                       std::size_t live);
RunStats summarize(std::size_t warmup, std::vector<WallRunStats> walls);

void logRunStats(const RunStats& stats);
// Throws Error naming the path when it cannot be written.
void writeRunStats(const RunStats& stats, const std::filesystem::path& path);

}  // namespace sandstorm
