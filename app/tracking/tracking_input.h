// TrackingInput: the tracked head and wand on the main context, once a frame.
// It owns the source (a DTrackReceiver, or the samples a replayed session
// recorded), the TrackingSampler and the WandController. Only the process
// that owns the main context makes one (rank 0 in cluster mode): walls get
// the result in the FramePacket.
//
// Replaying a session that recorded tracking, its samples are used frame by
// frame and no port is opened; the wand's requests are not made again (the
// session holds the changes they made), but its ray is cast and drawn as it
// was.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "app/tracking/tracker_source.h"
#include "core/sim/session_log.h"
#include "core/tracking/wand_controller.h"

namespace sandstorm {

struct TrackingStatus {
  std::string source;
  TrackerStats stats;
  bool waiting = true;  // nothing measured yet
  bool lost = false;    // stale: the last poses are held
  std::uint32_t trackerFrame = 0;
  bool wandPresent = false, wandTracked = false;  // the Flystick heard; its pose measured
};

class TrackingInput {
 public:
  // `replayed`: the tracking samples of a replayed session (may be empty).
  // `source`: a tracker already open (tests); null: opens what tracking.source names.
  // Throws Error when the source cannot start (the port, or source = replay without samples).
  TrackingInput(const TrackingSpec& tracking, const NavigationSpec& navigation,
                std::vector<ScheduledTracking> replayed,
                std::unique_ptr<TrackerSource> source = nullptr);
  // Whether a run with this configuration and replay needs one.
  static bool wanted(const TrackingSpec& tracking, const std::vector<ScheduledTracking>& replayed);

  bool replaying() const { return !replayed_.empty(); }
  // At the start of `frame`: the sample that frame uses.
  TrackingSample sample(std::uint32_t frame);
  WandActions wand(const TrackingSample& sample, const WandScene& scene, float dt);
  TrackingStatus status() const;

 private:
  std::unique_ptr<TrackerSource> source_;
  TrackingSampler sampler_;
  WandController wand_;
  std::vector<ScheduledTracking> replayed_;
  std::size_t replayAt_ = 0;
  TrackingSample last_;
};

}  // namespace sandstorm
