#include "app/run_stats.h"

#include <algorithm>
#include <sstream>

#include "core/util/log.h"
#include "core/util/output_file.h"

namespace sandstorm {
namespace {

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t i = std::min(v.size() - 1, std::size_t(q * double(v.size() - 1) + 0.5));
  return v[i];
}

}  // namespace

WallRunStats summarize(const std::string& name, const std::string& renderer,
                       const std::vector<WallFrameSample>& samples, std::size_t frames,
                       std::size_t live) {
  WallRunStats w;
  w.name = name;
  w.renderer = renderer;
  w.frames = frames;
  std::vector<double> interval, cpu, barrier, packet, stage[4], total;
  for (const WallFrameSample& s : samples) {
    if (s.intervalMs > 0.0) interval.push_back(s.intervalMs);
    cpu.push_back(s.cpuMs);
    barrier.push_back(s.waitMs);
    packet.push_back(s.packetWaitMs);
    if (s.gpu) {
      double sum = 0.0;
      for (int k = 0; k < 4; ++k) {
        stage[k].push_back((*s.gpu)[std::size_t(k)]);
        sum += (*s.gpu)[std::size_t(k)];
      }
      total.push_back(sum);
    }
  }
  w.frameMs = quantile(interval, 0.5);
  w.frameP95Ms = quantile(interval, 0.95);
  w.cpuMs = quantile(cpu, 0.5);
  w.updateMs = quantile(stage[0], 0.5);
  w.sceneMs = quantile(stage[1], 0.5);
  w.particlesMs = quantile(stage[2], 0.5);
  w.postMs = quantile(stage[3], 0.5);
  w.gpuMs = quantile(total, 0.5);
  w.barrierWaitMs = quantile(barrier, 0.5);
  w.packetWaitMs = quantile(packet, 0.5);
  w.live = live;
  return w;
}

RunStats summarize(std::size_t warmup, std::vector<WallRunStats> walls) {
  RunStats r;
  r.warmup = warmup;
  r.walls = std::move(walls);
  if (!r.walls.empty()) {
    r.frames = r.walls.front().frames;
    r.frameMs = r.walls.front().frameMs;
    r.frameP95Ms = r.walls.front().frameP95Ms;
    r.fps = r.frameMs > 0.0 ? 1000.0 / r.frameMs : 0.0;
  }
  return r;
}

void logRunStats(const RunStats& r) {
  if (r.frames == 0) {
    log::info("frame times: no frames after the warm-up of ", r.warmup);
    return;
  }
  log::info("frame times over ", r.frames, " frames after ", r.warmup, ": median ", r.frameMs,
            " ms (", r.fps, " frames/s), 95th percentile ", r.frameP95Ms, " ms");
  for (const WallRunStats& w : r.walls)
    log::info("  wall '", w.name, "' (", w.renderer, "): GPU median ", w.gpuMs, " ms = update ",
              w.updateMs, " + scene ", w.sceneMs, " + particles ", w.particlesMs, " + post ",
              w.postMs, "; thread ", w.cpuMs, " ms; waits: swap ", w.barrierWaitMs, " ms, packet ",
              w.packetWaitMs, " ms; ", w.live, " particles");
  if (const auto& p = r.playback)
    log::info("  field series over the measured frames: ", p->stepsPlayed, " step(s) played in ",
              p->seconds, " s: ", p->stepsPerSecond(), " steps a second; playback waited ",
              p->framesWaited, " of ", p->frames, " frame(s)");
}

void writeRunStats(const RunStats& r, const std::filesystem::path& path) {
  std::ostringstream j;
  j << "{\n  \"warmup_frames\": " << r.warmup << ",\n  \"frames\": " << r.frames
    << ",\n  \"frame_ms_median\": " << r.frameMs << ",\n  \"frame_ms_p95\": " << r.frameP95Ms
    << ",\n  \"fps\": " << r.fps << ",\n  \"walls\": [";
  for (std::size_t i = 0; i < r.walls.size(); ++i) {
    const WallRunStats& w = r.walls[i];
    j << (i ? "," : "") << "\n    {\"name\": \"" << w.name << "\", \"renderer\": \"" << w.renderer
      << "\", \"frames\": " << w.frames << ", \"frame_ms_median\": " << w.frameMs
      << ", \"frame_ms_p95\": " << w.frameP95Ms << ", \"thread_ms\": " << w.cpuMs
      << ", \"gpu_ms\": " << w.gpuMs << ", \"update_ms\": " << w.updateMs
      << ", \"scene_ms\": " << w.sceneMs << ", \"particles_ms\": " << w.particlesMs
      << ", \"post_ms\": " << w.postMs << ", \"swap_wait_ms\": " << w.barrierWaitMs
      << ", \"packet_wait_ms\": " << w.packetWaitMs << ", \"live_particles\": " << w.live << "}";
  }
  j << "\n  ]";
  if (r.tracking)
    j << ",\n  \"tracking\": {\"received\": " << r.tracking->received
      << ", \"dropped\": " << r.tracking->dropped << ", \"foreign\": " << r.tracking->foreign
      << "}";
  if (r.playback)
    j << ",\n  \"series\": {\"frames\": " << r.playback->frames
      << ", \"steps_played\": " << r.playback->stepsPlayed
      << ", \"seconds\": " << r.playback->seconds
      << ", \"steps_per_s\": " << r.playback->stepsPerSecond()
      << ", \"frames_waited\": " << r.playback->framesWaited << "}";
  j << "\n}\n";
  const std::string text = j.str();
  writeFile(path, text, "--stats");
}

}  // namespace sandstorm
