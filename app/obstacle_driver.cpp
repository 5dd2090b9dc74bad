#include "app/obstacle_driver.h"

#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {

ObstacleDriver::ObstacleDriver(std::vector<ObstaclePath> paths)
    : paths_(std::move(paths)), driving_(paths_.size(), false), placed_(paths_.size()) {}

void ObstacleDriver::start(MainContext& main) {
  place(main);
}

void ObstacleDriver::update(MainContext& main, const FramePacket& packet) {
  if (packet.reset) time_ = 0.0;
  time_ += double(packet.simDt);
  place(main);
}

void ObstacleDriver::place(MainContext& main) {
  const ParticleState state = main.pendingState();
  for (std::size_t i = 0; i < paths_.size() && i < state.obstacles.size(); ++i) {
    const std::string key = concat("obstacle.", i, ".");
    bool drive = !paths_[i].empty() && state.obstacles[i].path;
    if (drive && driving_[i] && state.obstacles[i].position != placed_[i]) {
      log::info("obstacle ", i, " was moved by hand: its path is off (", key, "path)");
      main.set(key + "path", false);
      drive = false;
    }
    if (drive) {
      const ObstaclePath::Sample s = paths_[i].at(time_);
      if (s.position != state.obstacles[i].position) main.set(key + "position", s.position);
      if (s.velocity != state.obstacles[i].velocity) main.set(key + "velocity", s.velocity);
      placed_[i] = s.position;
    } else if (driving_[i] && state.obstacles[i].velocity != glm::vec3(0.0f)) {
      main.set(key + "velocity", glm::vec3(0.0f));  // left where it is, at rest
    }
    driving_[i] = drive;
  }
}

}  // namespace sandstorm
