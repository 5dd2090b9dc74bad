#include "core/sim/level_of_detail.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sandstorm {

float viewCoverage(const Box& box, const FieldPlacement& placement, const Viewer& viewer) {
  const glm::vec3 center = placement.toRoom(box.center());
  const float radius = 0.5f * glm::length(box.max - box.min) * placement.scale;
  const glm::vec3 head = viewer.navigation.roomToWorld(viewer.head.position);
  const float distance = glm::length(center - head);
  if (distance <= radius) return 1.0f;
  const float cosTheta =
      std::sqrt(std::max(0.0f, 1.0f - (radius / distance) * (radius / distance)));
  const float solidAngle = 2.0f * std::numbers::pi_v<float> * (1.0f - cosTheta);
  const float view =
      2.0f * std::numbers::pi_v<float> * (1.0f - std::cos(std::numbers::pi_v<float> / 4.0f));
  return std::min(solidAngle / view, 1.0f);
}

float LevelOfDetail::update(const SimSettings& s, float coverage, std::optional<double> frameMs) {
  if (!s.lod) {
    budgetScale_ = scale_ = 1.0f;
    return scale_;
  }
  const float byCoverage = s.lodCoverage > 0.0f ? std::min(coverage / s.lodCoverage, 1.0f) : 1.0f;
  if (s.lodBudgetMs > 0.0f && frameMs && *frameMs > 0.0) {
    if (*frameMs > s.lodBudgetMs)
      budgetScale_ *= std::max(0.5f, float(s.lodBudgetMs / *frameMs));
    else if (*frameMs < 0.9 * s.lodBudgetMs)
      budgetScale_ = std::min(1.0f, budgetScale_ * 1.05f);
  } else {
    budgetScale_ = 1.0f;
  }
  budgetScale_ = std::max(budgetScale_, s.lodMinScale);
  scale_ = std::clamp(std::min(byCoverage, budgetScale_), s.lodMinScale, 1.0f);
  return scale_;
}

}  // namespace sandstorm
