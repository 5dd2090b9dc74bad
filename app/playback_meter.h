// PlaybackMeter: how fast a time-varying field played over the run's
// measured frames (after run.stats_warmup), in steps of the series a second
// of wall time. Each frame the main thread tells it the pair in use; a step
// counts once it comes into use (the pair's first step moves on: by the
// shorter way round the series, so playing backwards and looping count too).
// The wall time runs from the first measured frame's packet to the last
// one's, so start-up and the closing images are left out, and frames that
// waited for the disk are in it.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>

#include "core/sim/field_player.h"

namespace sandstorm {

struct PlaybackRunStats {
  std::uint64_t frames = 0;        // measured
  std::uint64_t stepsPlayed = 0;   // steps that came into use in them
  std::uint64_t framesWaited = 0;  // of them, frames that waited for a step
  double seconds = 0.0;            // their wall time
  double stepsPerSecond() const { return seconds > 0.0 ? double(stepsPlayed) / seconds : 0.0; }
};

class PlaybackMeter {
 public:
  using Clock = std::chrono::steady_clock;

  explicit PlaybackMeter(std::uint32_t warmup) : warmup_(warmup) {}

  // Frame `frame`'s packet made at `now`, with the field's playback as it went.
  void frame(std::uint32_t frame, const FieldPlaybackStatus& playback, Clock::time_point now);
  // Nothing until two measured frames were seen.
  std::optional<PlaybackRunStats> stats() const;

 private:
  std::uint32_t warmup_;
  std::optional<Clock::time_point> begin_;
  Clock::time_point last_;
  std::size_t first_ = 0;
  std::uint64_t waitedAtBegin_ = 0, waited_ = 0;
  std::uint64_t frames_ = 0, steps_ = 0;
};

}  // namespace sandstorm
