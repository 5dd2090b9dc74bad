#include "core/field/vorticity.h"

#include "core/field/velocity_gradient.h"

namespace sandstorm {

VectorField vorticityMagnitude(const VectorField& field) {
  const glm::ivec3 d = field.dims();
  std::vector<glm::vec3> values(field.pointCount(), glm::vec3(0.0f));
  for (int k = 0; k < d.z; ++k)
    for (int j = 0; j < d.y; ++j)
      for (int i = 0; i < d.x; ++i) {
        if (!field.valid(i, j, k)) continue;
        const glm::mat3 g = velocityGradient(field, {i, j, k});
        const glm::vec3 &dx = g[0], &dy = g[1], &dz = g[2];
        const glm::vec3 curl(dy.z - dz.y, dz.x - dx.z, dx.y - dy.x);
        values[field.index(i, j, k)] = glm::vec3(glm::length(curl), 0.0f, 0.0f);
      }
  VectorField out(field.bounds(), d, std::move(values));
  if (field.hasValidity())
    out.setValidity(std::vector<std::uint8_t>(field.validity().begin(), field.validity().end()));
  return out;
}

}  // namespace sandstorm
