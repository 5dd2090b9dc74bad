#include "core/field/gradient_noise.h"

#include <cmath>

namespace sandstorm {
namespace {

std::uint32_t hash(std::uint32_t x) {
  // A 32-bit integer finaliser (lowbias32).
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

float fade(float t) {
  return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}
float fadeDerivative(float t) {
  return 30.0f * t * t * (t * (t - 2.0f) + 1.0f);
}

}  // namespace

glm::vec3 GradientNoise::latticeGradient(const glm::ivec3& c) const {
  std::uint32_t h =
      hash(seed_ ^ hash(std::uint32_t(c.x) ^ hash(std::uint32_t(c.y) ^ hash(std::uint32_t(c.z)))));
  // One of the 12 edge directions of the cube, as in improved Perlin noise.
  static constexpr float kDirs[12][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                         {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                         {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};
  const float* d = kDirs[h % 12u];
  return {d[0], d[1], d[2]};
}

glm::vec4 GradientNoise::valueAndGradient(const glm::vec3& p) const {
  const glm::vec3 cellf = glm::floor(p);
  const glm::ivec3 cell(cellf);
  const glm::vec3 f = p - cellf;
  const glm::vec3 u(fade(f.x), fade(f.y), fade(f.z));
  const glm::vec3 du(fadeDerivative(f.x), fadeDerivative(f.y), fadeDerivative(f.z));

  // Corner contributions n_abc = g_abc . (f - abc), blended trilinearly in u.
  float n[2][2][2];
  glm::vec3 g[2][2][2];
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int c = 0; c < 2; ++c) {
        g[a][b][c] = latticeGradient(cell + glm::ivec3(a, b, c));
        n[a][b][c] = glm::dot(g[a][b][c], f - glm::vec3(a, b, c));
      }
  float value = 0.0f;
  glm::vec3 grad(0.0f);
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int c = 0; c < 2; ++c) {
        const float wx = a ? u.x : 1.0f - u.x, wy = b ? u.y : 1.0f - u.y, wz = c ? u.z : 1.0f - u.z;
        const float dwx = a ? du.x : -du.x, dwy = b ? du.y : -du.y, dwz = c ? du.z : -du.z;
        const float w = wx * wy * wz;
        value += w * n[a][b][c];
        grad +=
            w * g[a][b][c] + n[a][b][c] * glm::vec3(dwx * wy * wz, wx * dwy * wz, wx * wy * dwz);
      }
  return glm::vec4(grad, value);
}

}  // namespace sandstorm
