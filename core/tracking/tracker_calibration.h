// TrackerCalibration: from the tracker's room (DTrack: millimetres, its own
// axes) to Sandstorm's room (metres, z up):
//
//   room = offset + rotation * (tracker millimetres / 1000)
//
// and from each body's own axes to the canonical ones a TrackingSample
// carries (right, forward, up). The head's position is moved from the
// glasses' body origin to between the eyes by eye_offset (body axes, metres).
#pragma once

#include <optional>

#include "core/config/app_config.h"
#include "core/tracking/tracker_frame.h"
#include "core/tracking/tracking_sample.h"

namespace sandstorm {

class TrackerCalibration {
 public:
  // Throws Error when the configured body axes are not two perpendicular directions.
  explicit TrackerCalibration(const TrackingSpec& spec);

  glm::vec3 toRoom(const glm::vec3& trackerMillimetres) const;

  // The head body's pose in the room; nullopt when the frame does not hold it.
  std::optional<TrackedPose> head(const TrackerFrame& frame) const;
  // The wand's Flystick; nullopt when the frame does not hold it. An
  // untracked Flystick comes back with tracked = false and its buttons.
  std::optional<WandSample> wand(const TrackerFrame& frame) const;

 private:
  TrackedPose pose(const glm::vec3& millimetres, const glm::mat3& rotation,
                   const glm::mat3& bodyAxes) const;

  TrackingSpec spec_;
  glm::mat3 headAxes_{1.0f}, wandAxes_{1.0f};  // canonical axes in body coordinates (columns)
};

}  // namespace sandstorm
