// ValueRange: the smallest and largest speed and velocity components of a set
// of vectors, gathered one vector at a time and merged across threads (min
// and max do not depend on the order, so any split gives the same range).
// FieldRange builds a field's colour-scale ends from it; a reader that checks
// every value of a grid it has just read gathers it in that same pass
// (VectorField::rememberRange), so that the main context need not read a
// series' 200 MB step once more for it.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

namespace sandstorm {

struct ValueRange {
  // Squared speeds: min and max commute with the square root, so the speeds'
  // range is the square roots of these (glm::length's very values), and one
  // square root per field is taken instead of one per vector.
  float minSpeed2 = std::numeric_limits<float>::max();
  float maxSpeed2 = 0.0f;
  glm::vec3 minVelocity{std::numeric_limits<float>::max()};
  glm::vec3 maxVelocity{std::numeric_limits<float>::lowest()};
  bool any = false;  // whether any vector was added

  void add(const glm::vec3& v) {
    const float speed2 = glm::dot(v, v);
    minSpeed2 = std::min(minSpeed2, speed2);
    maxSpeed2 = std::max(maxSpeed2, speed2);
    minVelocity = glm::min(minVelocity, v);
    maxVelocity = glm::max(maxVelocity, v);
    any = true;
  }
  void merge(const ValueRange& o) {
    minSpeed2 = std::min(minSpeed2, o.minSpeed2);
    maxSpeed2 = std::max(maxSpeed2, o.maxSpeed2);
    minVelocity = glm::min(minVelocity, o.minVelocity);
    maxVelocity = glm::max(maxVelocity, o.maxVelocity);
    any = any || o.any;
  }
  float minSpeed() const { return std::sqrt(minSpeed2); }
  float maxSpeed() const { return std::sqrt(maxSpeed2); }
  bool operator==(const ValueRange&) const = default;
};

}  // namespace sandstorm
