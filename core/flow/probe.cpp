#include "core/flow/probe.h"

#include <algorithm>
#include <cmath>

namespace sandstorm {

std::optional<glm::vec3> probePoint(const ParticleState& state, const WandRay& wand,
                                    const Navigation& navigation) {
  if (!state.probe.enabled) return std::nullopt;
  if (!wand.visible) return state.probe.position;
  const glm::vec3 along = wand.end - wand.origin;
  if (!(glm::length(along) > 0.0f)) return state.probe.position;
  const glm::vec3 direction = glm::normalize(along);
  glm::vec3 room = wand.origin + state.probe.reach * direction;
  if (state.slice.enabled && glm::length(state.slice.normal) > 0.0f) {
    // The slice plane, carried into the room.
    const glm::mat4 toRoom = navigation.worldToRoom();
    const glm::vec3 origin = glm::vec3(toRoom * glm::vec4(state.slice.origin, 1.0f));
    const glm::vec3 normal =
        glm::normalize(glm::vec3(toRoom * glm::vec4(state.slice.normal, 0.0f)));
    const float facing = glm::dot(direction, normal);
    if (std::abs(facing) > 1e-6f) {
      const float t = glm::dot(origin - wand.origin, normal) / facing;
      if (t > 0.0f) room = wand.origin + t * direction;
    }
  }
  return navigation.roomToWorld(room);
}

glm::vec3 pickProbePoint(const ParticleState& state, const glm::vec3& origin,
                         const glm::vec3& direction, const glm::vec3& centre) {
  if (!(glm::length(direction) > 0.0f)) return centre;
  const glm::vec3 d = glm::normalize(direction);
  if (state.slice.enabled && glm::length(state.slice.normal) > 0.0f) {
    const glm::vec3 n = glm::normalize(state.slice.normal);
    const float facing = glm::dot(d, n);
    if (std::abs(facing) > 1e-6f) {
      const float t = glm::dot(state.slice.origin - origin, n) / facing;
      if (t > 0.0f) return origin + t * d;
    }
  }
  return origin + std::max(glm::dot(centre - origin, d), 0.0f) * d;
}

ProbeReading readProbe(const glm::vec3& point, const PhysicsInputs& in) {
  ProbeReading r;
  r.point = point;
  if (!in.field) return r;
  const glm::vec3 local = in.placement.toLocal(point);
  r.inside = particleDomain(*in.field).contains(local) && in.field->cellValid(local);
  if (!r.inside) return r;
  r.velocity = fieldAt(point, in);
  r.speed = glm::length(r.velocity);
  for (const VectorField::Scalars& s : in.field->scalars())
    r.scalars.emplace_back(s.name, in.field->sampleScalars(s, local));
  return r;
}

}  // namespace sandstorm
