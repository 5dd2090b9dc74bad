// An axis-aligned box in metres: the bounds of a field, an emitter or a view volume.
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

struct Box {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};

  glm::vec3 extent() const { return max - min; }
  glm::vec3 center() const { return 0.5f * (min + max); }
  bool contains(const glm::vec3& p) const {
    return glm::all(glm::greaterThanEqual(p, min)) && glm::all(glm::lessThanEqual(p, max));
  }
};

}  // namespace sandstorm
