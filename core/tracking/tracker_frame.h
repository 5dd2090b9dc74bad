// TrackerFrame: one measurement of an optical tracker (ART DTrack) as the
// tracker sent it: its frame counter and timestamp, the standard 6DOF bodies
// (the user's glasses), the Flysticks (wands) and single markers, in the
// tracker's own room coordinates and units (millimetres). Nothing here is in
// Sandstorm's room yet: TrackerCalibration maps it there.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace sandstorm {

// A 6DOF standard body. DTrack sends only tracked standard bodies.
struct TrackedBody {
  int id = 0;
  float quality = 1.0f;
  glm::vec3 position{0.0f};  // mm, tracker room
  glm::mat3 rotation{1.0f};  // body axes in the tracker room (columns)
};

// A Flystick (6df2, or the older 6df). Untracked Flysticks are still sent
// (quality < 0, zero position and matrix): their buttons stay valid.
struct TrackedFlystick {
  static constexpr int kMaxControllers = 8;  // kept; more are parsed and checked, then dropped

  int id = 0;
  float quality = 1.0f;
  glm::vec3 position{0.0f};  // mm
  glm::mat3 rotation{1.0f};
  int buttonCount = 0;
  std::uint32_t buttons = 0;  // bit i: button i pressed (the first 32)
  int controllerCount = 0;
  std::array<float, kMaxControllers> controllers{};  // joystick axes, -1..1

  bool tracked() const { return quality >= 0.0f; }
  bool pressed(int button) const {
    return button >= 0 && button < 32 && (buttons >> unsigned(button)) & 1u;
  }
};

// A single marker (3d).
struct TrackedMarker {
  int id = 0;
  float quality = 1.0f;
  glm::vec3 position{0.0f};  // mm
};

struct TrackerFrame {
  std::optional<std::uint32_t> frame;  // fr: the tracker's frame counter
  std::optional<double> timestamp;     // ts: seconds since midnight (UTC)
  std::vector<TrackedBody> bodies;
  std::vector<TrackedFlystick> flysticks;
  std::vector<TrackedMarker> markers;
  int skippedLines = 0;  // line types Sandstorm does not read (6di, gl, 6dmt, ...)

  const TrackedBody* body(int id) const;
  const TrackedFlystick* flystick(int id) const;
};

}  // namespace sandstorm
