#include "core/cave/viewer.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace sandstorm {

glm::vec3 rightOfYaw(float yaw) {
  return {std::sin(yaw), -std::cos(yaw), 0.0f};
}

Navigation Navigation::from(const NavigationSpec& spec) {
  return {spec.offset, glm::radians(spec.yawDegrees), spec.scale};
}

glm::mat4 Navigation::worldToRoom() const {
  return glm::translate(glm::mat4(1.0f), offset) *
         glm::rotate(glm::mat4(1.0f), yawRadians, {0, 0, 1}) *
         glm::scale(glm::mat4(1.0f), glm::vec3(scale));
}

glm::vec3 Navigation::roomToWorld(const glm::vec3& room) const {
  return glm::vec3(glm::inverse(worldToRoom()) * glm::vec4(room, 1.0f));
}

ScriptedHead::ScriptedHead(std::vector<HeadKeyframe> path, bool loop, const HeadPose& base)
    : path_(std::move(path)), loop_(loop), base_(base) {}

HeadPose ScriptedHead::pose(double time) const {
  HeadPose p = base_;
  if (path_.empty()) return p;
  const double start = path_.front().time, end = path_.back().time;
  double t = time + start;
  if (loop_ && end > start) t = start + std::fmod(time, end - start);
  t = std::clamp(t, start, end);
  auto next = std::upper_bound(path_.begin(), path_.end(), t,
                               [](double x, const HeadKeyframe& k) { return x < double(k.time); });
  if (next == path_.begin()) return p.position = path_.front().position, p;
  if (next == path_.end()) return p.position = path_.back().position, p;
  const HeadKeyframe& a = *(next - 1);
  const HeadKeyframe& b = *next;
  const float w = float((t - a.time) / double(b.time - a.time));
  p.position = glm::mix(a.position, b.position, w);
  return p;
}

DesktopHead::DesktopHead(const HeadPose& start, float yawRadians) : pose_(start), yaw_(yawRadians) {
  pose_.right = rightOfYaw(yaw_);
}

HeadPose DesktopHead::pose(double) const {
  return pose_;
}

void DesktopHead::move(float forward, float right, float up) {
  const glm::vec3 ahead(std::cos(yaw_), std::sin(yaw_), 0.0f);
  pose_.position += forward * ahead + right * pose_.right + glm::vec3(0, 0, up);
}

void DesktopHead::turn(float yawRadians) {
  yaw_ += yawRadians;
  pose_.right = rightOfYaw(yaw_);
}

std::unique_ptr<HeadTracker> makeHeadTracker(const HeadSpec& spec) {
  HeadPose base;
  base.position = spec.position;
  base.right = spec.right ? *spec.right : rightOfYaw(glm::radians(spec.yawDegrees));
  base.eyeSeparation = spec.eyeSeparation;
  switch (spec.mode) {
    case HeadMode::Fixed:
      return std::make_unique<FixedHead>(base);
    case HeadMode::Scripted:
      return std::make_unique<ScriptedHead>(spec.path, spec.loop, base);
    case HeadMode::Desktop:
      return std::make_unique<DesktopHead>(base, glm::radians(spec.yawDegrees));
  }
  return std::make_unique<FixedHead>(base);
}

}  // namespace sandstorm
