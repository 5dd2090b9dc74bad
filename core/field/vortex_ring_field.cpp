#include "core/field/vortex_ring_field.h"

#include <cmath>

#include "core/util/error.h"

namespace sandstorm {

VortexRingField::VortexRingField(const VortexRingParams& params) : params_(params) {
  if (!(params.ringRadius > 0.0f) || !(params.core > 0.0f))
    throw Error("VortexRingField: ring and core radii must be > 0");
}

glm::vec3 VortexRingField::evaluate(const glm::vec3& p) const {
  const glm::vec3 t = p - params_.center;
  const float r = std::sqrt(t.x * t.x + t.y * t.y);
  if (r < 1e-6f) return glm::vec3(0.0f);
  const glm::vec2 outward(t.x / r, t.y / r);
  // In the (radial, vertical) half-plane: offset from the core circle.
  const float dr = r - params_.ringRadius, dz = t.z - params_.height;
  const float d2 = dr * dr + dz * dz, c = params_.core;
  const float speed =
      params_.strength * 2.0f * c / (d2 + c * c);  // times d, below, gives the profile
  // Turning so that below the core (dz < 0) the flow runs outwards: (u_r, u_z) = speed * (-dz, dr).
  const float ur = -dz * speed, uz = dr * speed;
  return {outward.x * ur, outward.y * ur, uz};
}

}  // namespace sandstorm
