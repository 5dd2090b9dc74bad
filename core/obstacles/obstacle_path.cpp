#include "core/obstacles/obstacle_path.h"

#include <algorithm>
#include <cmath>

namespace sandstorm {

ObstaclePath::ObstaclePath(std::vector<ObstacleKeyframe> keys, bool loop)
    : keys_(std::move(keys)), loop_(loop) {}

ObstaclePath::Sample ObstaclePath::at(double time) const {
  if (keys_.empty()) return {};
  if (keys_.size() == 1) return {keys_.front().position, glm::vec3(0.0f)};
  const double start = keys_.front().time, span = double(keys_.back().time) - start;
  double t = start + std::max(time, 0.0);
  if (loop_ && span > 0.0) t = start + std::fmod(std::max(time, 0.0), span);
  if (t >= double(keys_.back().time)) return {keys_.back().position, glm::vec3(0.0f)};
  const auto next =
      std::upper_bound(keys_.begin(), keys_.end(), t,
                       [](double x, const ObstacleKeyframe& k) { return x < double(k.time); });
  const ObstacleKeyframe& a = *(next - 1);
  const ObstacleKeyframe& b = *next;
  const float length = b.time - a.time;
  const float w = float((t - double(a.time)) / double(length));
  return {glm::mix(a.position, b.position, w), (b.position - a.position) / length};
}

}  // namespace sandstorm
