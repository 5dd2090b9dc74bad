// TrackingSampler: turns the newest tracker measurement into one
// TrackingSample per frame, on the main context. A measurement is used by the
// first frame that starts after it arrived (the sampler is called at the start
// of each frame with whatever the receiver holds then).
//
// No fresh measurement of the head body for tracking.stale_ms: the last head
// pose is held, the sample says stale, and one warning is logged; when
// measurements return, one info line says so. The wand's pose is held the
// same way while measurements are missing; a measurement that reports it
// untracked (quality -1, occluded) makes it untracked at once, every time (its
// ray disappears). Its buttons and joystick follow the newest measurement
// whether tracked or not (DTrack sends them: a user flies on with the wand
// hidden), and read as released once the Flystick itself has not been heard
// of for stale_ms. Before the first measurement the sample is inactive and
// the configured head stands in.
#pragma once

#include <cstdint>
#include <optional>

#include "core/tracking/tracker_calibration.h"

namespace sandstorm {

// A complete tracker frame as a receiver keeps it.
struct TrackerMeasurement {
  TrackerFrame frame;
  std::uint64_t sequence = 0;   // counts received frames: a new number is a new measurement
  double arrivalSeconds = 0.0;  // on the clock the sampler is given
};

class TrackingSampler {
 public:
  explicit TrackingSampler(const TrackingSpec& spec);

  TrackingSample sample(const TrackerMeasurement* newest, double nowSeconds);
  bool lost() const { return lost_; }

 private:
  TrackingSpec spec_;
  TrackerCalibration calibration_;
  std::uint64_t lastSequence_ = 0;
  bool any_ = false;
  TrackingSample held_;
  double headSeconds_ = 0.0, wandSeconds_ = 0.0, flystickSeconds_ = 0.0;
  bool haveHead_ = false, haveWand_ = false;
  bool lost_ = false;
};

}  // namespace sandstorm
