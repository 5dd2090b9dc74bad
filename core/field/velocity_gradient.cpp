#include "core/field/velocity_gradient.h"

namespace sandstorm {
namespace {

glm::vec3 derivative(const VectorField& f, glm::ivec3 at, int axis, float h) {
  const glm::ivec3 d = f.dims();
  if (d[axis] < 2) return glm::vec3(0.0f);
  glm::ivec3 lo = at, hi = at;
  --lo[axis];
  ++hi[axis];
  const bool hasLo = lo[axis] >= 0 && f.valid(lo.x, lo.y, lo.z);
  const bool hasHi = hi[axis] < d[axis] && f.valid(hi.x, hi.y, hi.z);
  const glm::vec3 centre = f.at(at.x, at.y, at.z);
  if (hasLo && hasHi) return (f.at(hi.x, hi.y, hi.z) - f.at(lo.x, lo.y, lo.z)) / (2.0f * h);
  if (hasHi) return (f.at(hi.x, hi.y, hi.z) - centre) / h;
  if (hasLo) return (centre - f.at(lo.x, lo.y, lo.z)) / h;
  return glm::vec3(0.0f);
}

}  // namespace

glm::mat3 velocityGradient(const VectorField& field, glm::ivec3 at) {
  const glm::vec3 h = field.spacing();
  return glm::mat3(derivative(field, at, 0, h.x), derivative(field, at, 1, h.y),
                   derivative(field, at, 2, h.z));
}

}  // namespace sandstorm
