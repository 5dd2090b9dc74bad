#include "app/cluster/wall_gate.h"

#include <algorithm>

namespace sandstorm {

WallGate::WallGate(int walls) : drawn_(std::size_t(std::max(walls, 0)), -1) {}

void WallGate::drawn(int wall, std::uint32_t frame) {
  {
    std::lock_guard lock(mutex_);
    drawn_.at(std::size_t(wall)) = std::int64_t(frame);
  }
  changed_.notify_all();
}

WallGate::Result WallGate::wait(std::uint32_t frame, std::chrono::steady_clock::time_point deadline,
                                const std::function<bool()>& stop) {
  std::unique_lock lock(mutex_);
  for (;;) {
    if (std::all_of(drawn_.begin(), drawn_.end(),
                    [&](std::int64_t f) { return f >= std::int64_t(frame); }))
      return Result::Drawn;
    // A failed wall never reports again: look for failures between short waits.
    lock.unlock();
    const bool stopped = stop && stop();
    lock.lock();
    if (stopped) return Result::Stopped;
    if (std::chrono::steady_clock::now() > deadline) return Result::TimedOut;
    changed_.wait_for(lock, std::chrono::milliseconds(20));
  }
}

}  // namespace sandstorm
