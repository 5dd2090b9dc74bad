#include "core/light/light_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/light/puff_sprite.h"

namespace sandstorm {

LightFrame lightFrame(glm::vec3 towardsLight) {
  const float len = glm::length(towardsLight);
  const glm::vec3 n = len > 0.0f ? towardsLight / len : glm::vec3(0.0f, 0.0f, 1.0f);
  // Any axis not along the light: x, unless the light lies (nearly) along x.
  const glm::vec3 axis =
      std::abs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  const glm::vec3 right = glm::normalize(glm::cross(axis, n));
  return {right, glm::cross(n, right), n};
}

float particleCrossSection(float diameter, float opacity, float density) {
  const float blocked = std::min(opacity * puffCoverage(), 0.999f);
  const float r = 0.5f * diameter;
  return std::numbers::pi_v<float> * r * r * -std::log(1.0f - blocked) * density;
}

}  // namespace sandstorm
