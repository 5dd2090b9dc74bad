// GradientNoise: smooth 3D gradient (Perlin) noise with its exact gradient, the
// building block of the wind and curl-noise fields.
//
// value(p) is in about [-1, 1], zero at every integer lattice point, and C2
// smooth (quintic fade), so curl(noise) is C1 and its divergence is zero up to
// rounding. The lattice gradients come from an integer hash of (cell, seed):
// no tables, the same numbers on every platform, cheap to port to GLSL.
// Stateless after construction: safe to share between threads.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace sandstorm {

class GradientNoise {
 public:
  explicit GradientNoise(std::uint32_t seed = 0) : seed_(seed) {}

  float value(const glm::vec3& p) const { return valueAndGradient(p).w; }
  // (d/dx, d/dy, d/dz, value) at p.
  glm::vec4 valueAndGradient(const glm::vec3& p) const;

 private:
  glm::vec3 latticeGradient(const glm::ivec3& cell) const;
  std::uint32_t seed_;
};

}  // namespace sandstorm
