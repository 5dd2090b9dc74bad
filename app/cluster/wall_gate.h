// WallGate: where a rank's main thread learns that its walls have drawn a
// frame. Wall threads report each frame they finish (before they wait at the
// swap barrier); the main thread waits for all of them, then joins the
// cluster-wide barrier on their behalf, so render threads never call MPI.
// No MPI here.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <vector>

namespace sandstorm {

class WallGate {
 public:
  enum class Result { Drawn, Stopped, TimedOut };

  explicit WallGate(int walls);

  // A wall thread finished drawing `frame`.
  void drawn(int wall, std::uint32_t frame);

  // Waits until every wall has drawn `frame`; checks `stop` (a wall failed) now and then.
  Result wait(std::uint32_t frame, std::chrono::steady_clock::time_point deadline,
              const std::function<bool()>& stop);

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<std::int64_t> drawn_;  // per wall: the last frame drawn, -1 before the first
};

}  // namespace sandstorm
