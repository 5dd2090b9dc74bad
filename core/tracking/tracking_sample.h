// TrackingSample: the tracked user at one frame, in Sandstorm's room (metres,
// z up), as the main context sampled it once for every wall, thread and MPI
// rank. Orientations are canonical whatever the tracker's body calibration:
// the columns of `axes` are the body's right, forward and up directions.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace sandstorm {

struct TrackedPose {
  glm::vec3 position{0.0f};
  glm::mat3 axes{1.0f};  // columns: right, forward, up (room)

  glm::vec3 right() const { return axes[0]; }
  glm::vec3 forward() const { return axes[1]; }
  glm::vec3 up() const { return axes[2]; }
  bool operator==(const TrackedPose&) const = default;
};

struct WandSample {
  bool present = false;       // the Flystick is known (its buttons are valid)
  bool tracked = false;       // its pose is valid (measured, or held within tracking.stale_ms)
  TrackedPose pose;           // the wand's tip; forward() is where it points
  std::uint32_t buttons = 0;  // bit i: button i pressed
  glm::vec2 joystick{0.0f};   // x right, y up, -1..1 (live while present, tracked or not)

  bool pressed(int button) const {
    return button >= 0 && button < 32 && (buttons >> unsigned(button)) & 1u;
  }
  bool operator==(const WandSample&) const = default;
};

struct TrackingSample {
  bool active = false;             // a tracker (or a replayed session) drives this frame
  bool stale = false;              // no fresh head measurement within tracking.stale_ms: held
  std::uint32_t trackerFrame = 0;  // the tracker's own frame counter of the measurement used
  bool headTracked = false;        // `head` is a measured pose (fresh or held)
  TrackedPose head;                // between the eyes
  WandSample wand;

  bool operator==(const TrackingSample&) const = default;
};

}  // namespace sandstorm
