// FramePacer: holds a loop to at most a given number of frames a second
// (run.max_fps), as a display's refresh holds a windowed run. Headless runs
// on a fast GPU otherwise race ahead of the clock: a tracked session recorded
// headless then sees the tracker's seconds pass in a few frames.
//
// wait() returns at the frame's deadline, one period after the last; a loop
// that fell behind (a slow frame) starts counting again from now rather than
// hurrying through frames to catch up.
#pragma once

#include <chrono>
#include <thread>

namespace sandstorm {

class FramePacer {
 public:
  using Clock = std::chrono::steady_clock;

  // `framesPerSecond` <= 0: no limit.
  explicit FramePacer(double framesPerSecond)
      : period_(framesPerSecond > 0.0 ? std::chrono::duration_cast<Clock::duration>(
                                            std::chrono::duration<double>(1.0 / framesPerSecond))
                                      : Clock::duration::zero()) {}

  // Sleeps until one period after the last wait() ended (or after now).
  void wait() {
    if (period_ == Clock::duration::zero()) return;
    const Clock::time_point now = Clock::now();
    next_ =
        (next_ == Clock::time_point{} || next_ + period_ < now) ? now + period_ : next_ + period_;
    std::this_thread::sleep_until(next_);
  }

  Clock::duration period() const { return period_; }

 private:
  Clock::duration period_;
  Clock::time_point next_{};
};

}  // namespace sandstorm
