// TrackerScript: a scripted user, for sandstorm-tracker-sim: the head and the
// wand as keyframes in time, turned into the TrackerFrame an ART DTrack
// system would measure. Positions are in the tracker's room in metres (the
// frame carries DTrack's millimetres); orientations are yaw (about z, from
// +x: 90 faces +y), pitch (up) and, for the head, roll, in degrees. The
// bodies are "calibrated due to room" facing +y: at yaw 90, pitch 0 their
// rotation is the identity (TrackingSpec's default axes).
//
// Between keyframes positions and angles move linearly; buttons, the joystick
// and visibility hold until the next keyframe. A path file is TOML:
//
//   loop = true              # start again after the last keyframe
//   head_body = 0            # ids in the datagrams
//   wand_flystick = 0
//   [[key]]
//   time = 0.0
//   head = [0.0, 0.0, 1.7]
//   head_yaw_deg = 90.0      # also head_pitch_deg, head_roll_deg
//   wand = [0.2, 0.4, 1.2]
//   wand_yaw_deg = 90.0      # also wand_pitch_deg
//   buttons = 0              # bit i: Flystick button i (0: trigger)
//   joystick = [0.0, 0.0]
//   head_visible = true      # false: the glasses leave the tracked volume
//   wand_visible = true
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/tracking/tracker_frame.h"

namespace sandstorm {

struct TrackerKey {
  double time = 0.0;
  glm::vec3 head{0.0f, 0.0f, 1.7f};
  float headYawDeg = 90.0f, headPitchDeg = 0.0f, headRollDeg = 0.0f;
  glm::vec3 wand{0.2f, 0.4f, 1.2f};
  float wandYawDeg = 90.0f, wandPitchDeg = 0.0f;
  std::uint32_t buttons = 0;
  glm::vec2 joystick{0.0f};
  bool headVisible = true, wandVisible = true;
};

class TrackerScript {
 public:
  // A head walking round a 3 m CAVE looking about, a wand sweeping in front
  // of it, pressing buttons 2 and 3 (which Sandstorm leaves unassigned): it moves
  // the view and the ray, and changes nothing else.
  static TrackerScript builtIn();
  // Throws Error "file:line: key: what was expected".
  static TrackerScript load(const std::filesystem::path& path);
  static TrackerScript parse(const std::string& text, const std::string& name);

  TrackerFrame at(double seconds, std::uint32_t frame) const;
  double duration() const { return keys.back().time - keys.front().time; }

  std::vector<TrackerKey> keys;  // set by the constructors; times increase
  bool loop = true;
  int headBody = 0;
  int wandFlystick = 0;

 private:
  TrackerKey sampleKeys(double seconds) const;
};

// A body's rotation in the tracker room from its yaw, pitch and roll (degrees).
glm::mat3 bodyRotation(float yawDeg, float pitchDeg, float rollDeg);

}  // namespace sandstorm
