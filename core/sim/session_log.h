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
//   301 track frame=8812 stale=0 head=x,y,z,r0..r8 wand=present,tracked,x,y,z,r0..r8,buttons,jx,jy
//   302 navigate 0.5,2.6,0,0.1,0.35        (offset x y z, yaw in radians, scale)
//   400 field data/tornado.vti              (the menu loaded this field; or analytic:NAME)
//   460 field-step 2.5 /runs/sim/step_003.vti  (a watched field's step, its time, appended)
//   470 field-wait                          (a streamed field's playback waited for the disk)
//
// A `track` line is the tracking sample the frame used (core/tracking), in
// room coordinates, written when it differs from the frame before; a
// `navigate` line is the navigation (world -> room) from that frame on. Floats
// are written so they read back bit for bit, so a tracked CAVE session
// replays without the tracker and draws the same images.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/cave/viewer.h"
#include "core/sim/state_change.h"
#include "core/tracking/tracking_sample.h"

namespace sandstorm {

struct ScheduledChange {
  std::uint32_t frame = 0;
  StateChange change;
};

struct ScheduledTracking {
  std::uint32_t frame = 0;
  TrackingSample sample;
};

struct ScheduledNavigation {
  std::uint32_t frame = 0;
  Navigation navigation;
};

struct ScheduledField {
  std::uint32_t frame = 0;
  std::string source;  // a menu choice: "analytic:tornado", or a file relative to the project
};

struct ScheduledFieldStep {
  std::uint32_t frame = 0;
  double time = 0.0;  // the step's time in the field's timeline
  std::string file;   // as the watched source named it
};

struct SessionLog {
  std::vector<ScheduledChange> changes;
  std::vector<ScheduledField> fields;           // in frame order
  std::vector<ScheduledFieldStep> fieldSteps;   // in frame order
  std::set<std::uint32_t> fieldWaits;           // frames a streamed field's playback waited
  std::vector<ScheduledTracking> tracking;      // in frame order
  std::vector<ScheduledNavigation> navigation;  // in frame order
};

std::string formatChange(const StateChange& change);
std::string formatTracking(const TrackingSample& sample);
std::string formatNavigation(const Navigation& navigation);

// Parses a session log. Throws Error "file:line: ..." on the first bad line.
SessionLog readSession(const std::filesystem::path& path);
SessionLog parseSession(const std::string& text, const std::string& name);
// The changes alone.
std::vector<ScheduledChange> readSessionLog(const std::filesystem::path& path);
std::vector<ScheduledChange> parseSessionLog(const std::string& text, const std::string& name);

// Appends changes to a file as they happen (thread-safe).
class SessionRecorder {
 public:
  explicit SessionRecorder(const std::filesystem::path& path);
  void record(std::uint32_t frame, const StateChange& change);
  // Written only when different from the last one recorded.
  void recordTracking(std::uint32_t frame, const TrackingSample& sample);
  void recordNavigation(std::uint32_t frame, const Navigation& navigation);
  void recordField(std::uint32_t frame, const std::string& source);
  void recordFieldStep(std::uint32_t frame, double time, const std::string& file);
  void recordFieldWait(std::uint32_t frame);
  // Set once a write failed (a full disk): the run should stop and say so.
  std::optional<std::string> error() const;

 private:
  mutable std::mutex mutex_;
  std::ofstream out_;
  std::filesystem::path path_;
  std::optional<TrackingSample> lastTracking_;
  std::optional<Navigation> lastNavigation_;
  std::optional<std::string> error_;
  void checkWritten();
};

}  // namespace sandstorm
