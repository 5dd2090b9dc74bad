// Where the viewer is: the tracked head (and so the eyes), and where the world
// sits in the room (navigation). The main context samples both once per frame
// and ships them in the frame packet, so every wall draws the same instant.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/config/app_config.h"

namespace sandstorm {

struct HeadPose {
  glm::vec3 position{0.0f, 0.0f, 1.7f};  // between the eyes, room metres
  glm::vec3 right{1.0f, 0.0f, 0.0f};     // unit vector from the left eye to the right eye
  float eyeSeparation = 0.065f;

  glm::vec3 leftEye() const { return position - right * (0.5f * eyeSeparation); }
  glm::vec3 rightEye() const { return position + right * (0.5f * eyeSeparation); }
};

// The world-to-room transform: room = offset + scale * Rz(yaw) * world.
struct Navigation {
  glm::vec3 offset{0.0f};
  float yawRadians = 0.0f;
  float scale = 1.0f;

  static Navigation from(const NavigationSpec& spec);
  glm::mat4 worldToRoom() const;
  glm::vec3 roomToWorld(const glm::vec3& room) const;
};

struct Viewer {
  HeadPose head;
  Navigation navigation;
};

// A source of head poses. Time is the main context's clock, in seconds.
class HeadTracker {
 public:
  virtual ~HeadTracker() = default;
  virtual HeadPose pose(double time) const = 0;
};

class FixedHead final : public HeadTracker {
 public:
  explicit FixedHead(const HeadPose& pose) : pose_(pose) {}
  HeadPose pose(double) const override { return pose_; }

 private:
  HeadPose pose_;
};

// Moves through keyframes, linearly between them; loops or holds the last.
class ScriptedHead final : public HeadTracker {
 public:
  ScriptedHead(std::vector<HeadKeyframe> path, bool loop, const HeadPose& base);
  HeadPose pose(double time) const override;

 private:
  std::vector<HeadKeyframe> path_;
  bool loop_;
  HeadPose base_;
};

// The desktop simulator: input moves the head and turns it. Thread-safe
// enough for one writer (the input thread) and one reader (the main context),
// as the main context reads it on the same thread that polls input.
class DesktopHead final : public HeadTracker {
 public:
  explicit DesktopHead(const HeadPose& start, float yawRadians);
  HeadPose pose(double) const override;
  // Moves in the head's own frame: forward, right, up (metres).
  void move(float forward, float right, float up);
  void turn(float yawRadians);
  float yaw() const { return yaw_; }

 private:
  HeadPose pose_;
  float yaw_;
};

std::unique_ptr<HeadTracker> makeHeadTracker(const HeadSpec& spec);

// A head facing `yawRadians` (counter-clockwise from +x): its right vector.
glm::vec3 rightOfYaw(float yawRadians);

}  // namespace sandstorm
