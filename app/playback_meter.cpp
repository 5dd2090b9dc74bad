#include "app/playback_meter.h"

#include <algorithm>

namespace sandstorm {

void PlaybackMeter::frame(std::uint32_t frame, const FieldPlaybackStatus& playback,
                          Clock::time_point now) {
  if (frame < warmup_) {
    first_ = playback.first;
    return;
  }
  if (!begin_) {
    begin_ = now;
    waitedAtBegin_ = playback.framesWaited;
  } else if (playback.first != first_ && playback.steps > 0) {
    // Steps passed, either way round the series (a loop wraps).
    const std::size_t n = playback.steps;
    const std::size_t ahead = (playback.first + n - first_ % n) % n;
    steps_ += std::min(ahead, n - ahead);
  }
  first_ = playback.first;
  last_ = now;
  waited_ = playback.framesWaited;
  ++frames_;
}

std::optional<PlaybackRunStats> PlaybackMeter::stats() const {
  if (!begin_ || frames_ < 2) return std::nullopt;
  PlaybackRunStats s;
  s.frames = frames_;
  s.stepsPlayed = steps_;
  s.framesWaited = waited_ - waitedAtBegin_;
  s.seconds = std::chrono::duration<double>(last_ - *begin_).count();
  return s;
}

}  // namespace sandstorm
