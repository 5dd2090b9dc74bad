// ProgressBoard: the long work under way now (ProgressMeter), for whoever
// shows it beside the log: the loading window (app/load_with_window.h). Each
// meter is on the board from its making to its end; a snapshot describes the
// newest, with its share done, rate and time left worked out as the log's.
// Thread-safe: meters run on loader threads, the window reads on the main one.
#pragma once

#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace sandstorm {

class ProgressMeter;

struct ProgressSnapshot {
  std::string what;                   // "reading wind.vti"
  std::string unit;                   // "bytes"
  std::uint64_t done = 0, total = 0;  // total 0: open-ended
  double seconds = 0.0;               // since the work began
  double rate = 0.0;                  // units a second
  double secondsLeft = 0.0;           // at that rate; 0 when open-ended
  // The share done, 0..1; 0 when open-ended.
  double fraction() const;
  // One line as the log says it: "reading wind.vti: 41% (572 of 1400 MB), 1.2 GB/s, 0.7 s left".
  std::string text() const;
};

class ProgressBoard {
 public:
  static ProgressBoard& instance();

  // The newest work on the board, or none.
  std::optional<ProgressSnapshot> snapshot() const;

 private:
  friend class ProgressMeter;
  void add(const ProgressMeter* meter);
  void remove(const ProgressMeter* meter);

  mutable std::mutex mutex_;
  std::vector<const ProgressMeter*> meters_;
};

}  // namespace sandstorm
