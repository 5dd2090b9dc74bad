// The probe: a point where the scientist reads the flow. With a tracked wand
// it is where the wand's ray meets the slice plane (slice on and the plane in
// front of the wand), or `reach` metres (room) along the ray; otherwise
// probe.position. Every wall and the main context compute it from the same
// packet, so it needs no state change per frame.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/cave/viewer.h"
#include "core/sim/particle_physics.h"
#include "core/sim/particle_state.h"
#include "core/tracking/wand_ray.h"

namespace sandstorm {

// In the particles' coordinates; none while probe.enabled is off.
std::optional<glm::vec3> probePoint(const ParticleState& state, const WandRay& wand,
                                    const Navigation& navigation);

// The point a click on a desktop window picks for probe.position, from the
// ray through the clicked pixel (particles' coordinates; `direction` need not
// be unit): where it meets the slice plane (slice on and the plane in front),
// else its point nearest `centre` (the field's centre), never behind the eye.
glm::vec3 pickProbePoint(const ParticleState& state, const glm::vec3& origin,
                         const glm::vec3& direction, const glm::vec3& centre);

// The field there, as the particles feel it (fieldAt).
struct ProbeReading {
  glm::vec3 point{0.0f};
  bool inside = false;  // within the field's valid cells
  glm::vec3 velocity{0.0f};
  float speed = 0.0f;
  // The field file's scalar arrays there (name, value), in the file's order.
  std::vector<std::pair<std::string, float>> scalars;
};
ProbeReading readProbe(const glm::vec3& point, const PhysicsInputs& in);

}  // namespace sandstorm
