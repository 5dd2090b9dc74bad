// Session logs: every change the main context applied, with its frame, as
// text (the thesis's F11: attributes change programmatically as well as live).
// A recorded session replayed onto the same configuration reproduces the run
// exactly: the same changes at the same frames give the same particles.
//
//   # frame  change
//   120 set emitter.0.rate 50000
//   180 add-emitter shape=disc position=0,0,1 rate=2000
//   240 remove-emitter 1
//   300 reset
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <vector>

#include "core/sim/state_change.h"

namespace sandstorm {

struct ScheduledChange {
  std::uint32_t frame = 0;
  StateChange change;
};

std::string formatChange(const StateChange& change);

// Parses a session log. Throws Error "file:line: ..." on the first bad line.
std::vector<ScheduledChange> readSessionLog(const std::filesystem::path& path);
std::vector<ScheduledChange> parseSessionLog(const std::string& text, const std::string& name);

// Appends changes to a file as they happen (thread-safe).
class SessionRecorder {
 public:
  explicit SessionRecorder(const std::filesystem::path& path);
  void record(std::uint32_t frame, const StateChange& change);

 private:
  std::mutex mutex_;
  std::ofstream out_;
  std::filesystem::path path_;
};

}  // namespace sandstorm
