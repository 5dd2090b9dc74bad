// ObstaclePath: a scripted motion for an obstacle (the Mali sample's sphere
// moved about the floor): keyframes of (time, position), straight between
// them, looping or holding the last. Played on simulated time by the main
// context's side (app/obstacle_driver.h), which sets the obstacle's position
// and velocity attributes each frame, so every wall sees one motion.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace sandstorm {

struct ObstacleKeyframe {
  float time = 0.0f;  // s, increasing
  glm::vec3 position{0.0f};
};

class ObstaclePath {
 public:
  ObstaclePath() = default;
  // Needs at least two keyframes with increasing times (the loader checks).
  ObstaclePath(std::vector<ObstacleKeyframe> keys, bool loop);

  struct Sample {
    glm::vec3 position{0.0f};
    glm::vec3 velocity{0.0f};  // the slope of the segment it is on; 0 once held
  };
  // At `time` seconds after the start (keyframe times are offsets from the first).
  Sample at(double time) const;
  bool empty() const { return keys_.size() < 2; }
  const std::vector<ObstacleKeyframe>& keys() const { return keys_; }
  bool loops() const { return loop_; }

 private:
  std::vector<ObstacleKeyframe> keys_;
  bool loop_ = true;
};

}  // namespace sandstorm
