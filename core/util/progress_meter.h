// ProgressMeter: what a long piece of work (loading, resampling) has done,
// logged at info level to stderr as it goes: the amount done of the total,
// the rate and the time left, e.g.
//   [sandstorm info] resampling wind.vtu: 41% (572000 of 1400000 cells), 1.2e+06 cells/s, 0.7 s
//   left [sandstorm info] reading wind.vti: 56% (49.3 MB of 86.5 MB), 49.0 MB/s, 0.8 s left
// (ProgressSnapshot::text()).
// Work that ends within its first second says nothing. add() may be called
// from any thread; a line is written at most once a second, by whichever
// thread finds the second over. While it lives it is on the ProgressBoard,
// where a window may show it too.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

#include "core/util/progress_board.h"

namespace sandstorm {

class ProgressMeter {
 public:
  // `what`: "resampling wind.vtu"; `unit`: what is counted, plural ("cells");
  // `total` 0: open-ended (no share or time left is said).
  ProgressMeter(std::string what, std::uint64_t total, std::string unit);
  ~ProgressMeter();
  ProgressMeter(const ProgressMeter&) = delete;
  ProgressMeter& operator=(const ProgressMeter&) = delete;

  void add(std::uint64_t done);
  // Logs the total time when the work took long enough to have said anything.
  void finish();
  // What is done now, the rate and the time left (ProgressBoard).
  ProgressSnapshot snapshot() const;

 private:
  using Clock = std::chrono::steady_clock;
  void report(Clock::time_point now);

  std::string what_, unit_;
  std::uint64_t total_;
  std::atomic<std::uint64_t> done_{0};
  Clock::time_point start_;
  std::atomic<std::int64_t> nextReportNs_;
  std::mutex mutex_;
  bool said_ = false;
};

}  // namespace sandstorm
