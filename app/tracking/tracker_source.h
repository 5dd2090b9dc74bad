// TrackerSource: where the main context gets tracker measurements. A source
// keeps the newest complete measurement (on its own thread if it needs one);
// the main context takes it at the start of each frame (TrackingSampler) and
// never waits for it.
//
// DTrackReceiver (ART DTrack over UDP) is the one built. Another tracker
// plugs in behind the same interface: a VRPN client, say, would run its
// vrpn_Tracker_Remote/vrpn_Button_Remote/vrpn_Analog_Remote callbacks on its
// own thread, fill a TrackerFrame (bodies by sensor number, a Flystick with
// its buttons and joystick axes) in the tracker's millimetres, and hand it
// out here; the calibration, staleness, wand, packets and replays then work
// unchanged.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/tracking/tracking_sampler.h"

namespace sandstorm {

struct TrackerStats {
  std::uint64_t received = 0;  // complete measurements taken
  std::uint64_t dropped = 0;   // datagrams refused (malformed, oversized)
  std::uint64_t foreign = 0;   // datagrams from hosts not in tracking.sender, dropped
  std::string lastError;       // why the last one was refused
};

class TrackerSource {
 public:
  virtual ~TrackerSource() = default;
  virtual std::optional<TrackerMeasurement> newest() const = 0;
  virtual TrackerStats stats() const = 0;
  virtual std::string describe() const = 0;
};

// Seconds on the steady clock: the clock measurements' arrival times use.
double steadySeconds();

}  // namespace sandstorm
