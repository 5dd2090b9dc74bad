#include "core/field/vorticity.h"

namespace sandstorm {
namespace {

// d v / d x_axis at (i, j, k): central where both neighbours have data,
// one-sided where one has, 0 where none has or the axis has one point.
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

VectorField vorticityMagnitude(const VectorField& field) {
  const glm::ivec3 d = field.dims();
  const glm::vec3 h = field.spacing();
  std::vector<glm::vec3> values(field.pointCount(), glm::vec3(0.0f));
  for (int k = 0; k < d.z; ++k)
    for (int j = 0; j < d.y; ++j)
      for (int i = 0; i < d.x; ++i) {
        if (!field.valid(i, j, k)) continue;
        const glm::ivec3 at(i, j, k);
        const glm::vec3 dx = derivative(field, at, 0, h.x), dy = derivative(field, at, 1, h.y),
                        dz = derivative(field, at, 2, h.z);
        const glm::vec3 curl(dy.z - dz.y, dz.x - dx.z, dx.y - dy.x);
        values[field.index(i, j, k)] = glm::vec3(glm::length(curl), 0.0f, 0.0f);
      }
  VectorField out(field.bounds(), d, std::move(values));
  if (field.hasValidity())
    out.setValidity(std::vector<std::uint8_t>(field.validity().begin(), field.validity().end()));
  return out;
}

}  // namespace sandstorm
