#include "core/tracking/tracker_calibration.h"

#include <cmath>

#include "core/util/error.h"

namespace sandstorm {
namespace {

// Columns right, forward, up from two of them; throws unless they are perpendicular directions.
glm::mat3 axesFrom(const glm::vec3& a, const glm::vec3& b, const char* names, bool headStyle) {
  const float la = glm::length(a), lb = glm::length(b);
  if (!(la > 1e-6f) || !(lb > 1e-6f) || std::abs(glm::dot(a, b)) > 1e-3f * la * lb)
    throw Error(concat("tracking.", names, ": expected two perpendicular, non-zero directions"));
  const glm::vec3 u = a / la, v = b / lb;
  // Head: a = right, b = up. Wand: a = forward, b = up.
  if (headStyle) return glm::mat3(u, glm::cross(v, u), v);
  return glm::mat3(glm::cross(u, v), u, v);
}

}  // namespace

TrackerCalibration::TrackerCalibration(const TrackingSpec& spec)
    : spec_(spec),
      headAxes_(axesFrom(spec.headRight, spec.headUp, "head_right/head_up", true)),
      wandAxes_(axesFrom(spec.wandForward, spec.wandUp, "wand_forward/wand_up", false)) {}

glm::vec3 TrackerCalibration::toRoom(const glm::vec3& mm) const {
  return spec_.offset + spec_.rotation * (mm * 0.001f);
}

TrackedPose TrackerCalibration::pose(const glm::vec3& mm, const glm::mat3& rotation,
                                     const glm::mat3& bodyAxes) const {
  const glm::mat3 body = spec_.rotation * rotation;  // body axes in the room
  return TrackedPose{toRoom(mm), body * bodyAxes};
}

std::optional<TrackedPose> TrackerCalibration::head(const TrackerFrame& frame) const {
  const TrackedBody* b = frame.body(spec_.headBody);
  if (!b || b->quality < 0.0f) return std::nullopt;
  TrackedPose p = pose(b->position, b->rotation, headAxes_);
  p.position += spec_.rotation * b->rotation * spec_.eyeOffset;
  return p;
}

std::optional<WandSample> TrackerCalibration::wand(const TrackerFrame& frame) const {
  const TrackedFlystick* s = frame.flystick(spec_.wandFlystick);
  if (!s) return std::nullopt;
  WandSample w;
  w.present = true;
  w.tracked = s->tracked();
  if (w.tracked) w.pose = pose(s->position, s->rotation, wandAxes_);
  w.buttons = s->buttons;
  if (s->controllerCount > 0) w.joystick.x = s->controllers[0];
  if (s->controllerCount > 1) w.joystick.y = s->controllers[1];
  return w;
}

}  // namespace sandstorm
