// ObstacleDriver: moves the obstacles along their scripted paths
// ([[obstacle]] path, core/obstacles/obstacle_path.h), on the main thread, on
// simulated time (so a fixed-step run or a replay moves them the same, and a
// pause stops them). Each frame it asks the main context for the position and
// velocity of each obstacle whose path is on: ordinary attribute changes, so
// every wall moves it at one frame. An obstacle whose path is switched off
// (obstacle.N.path) stays where it is, at rest; one moved by anything else
// (the menu, the mouse, the wand) has its path switched off, so the hand wins.
// A replayed session needs no driver: it recorded the paths' moves.
#pragma once

#include <vector>

#include "core/obstacles/obstacle_path.h"
#include "core/sim/main_context.h"

namespace sandstorm {

class ObstacleDriver {
 public:
  explicit ObstacleDriver(std::vector<ObstaclePath> paths);
  // Before packet 0: each path's start.
  void start(MainContext& main);
  // After each packet: its simulated time passed; the next frame's places.
  void update(MainContext& main, const FramePacket& packet);

 private:
  void place(MainContext& main);

  std::vector<ObstaclePath> paths_;
  std::vector<bool> driving_;      // by obstacle: moved by its path last frame
  std::vector<glm::vec3> placed_;  // by obstacle: where its path put it last
  double time_ = 0.0;              // simulated seconds since the start
};

}  // namespace sandstorm
