// The downdraft demo's helicopter as solid parts: what the scene draws and
// what the dust collides with (the thesis's future work: "particles colliding
// with the helicopter"). Axis-aligned boxes for the fuselage, tail boom, fin
// and mast, and a flat cylinder for the rotor disc; they hang from the hub,
// which is helicopter.altitude above the ground under it.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "core/field/height_map.h"
#include "core/obstacles/obstacle.h"
#include "core/sim/helicopter.h"

namespace sandstorm {

struct HelicopterPart {
  ObstacleShape shape = ObstacleShape::Box;
  glm::vec3 center{0.0f};  // m, from the hub
  glm::vec3 size{0.0f};    // m: a box's extent; a cylinder's diameter, diameter, height
  glm::vec3 color{0.0f};
  // Body: drawn and solid; Blade: drawn only (the blades sweep the disc);
  // Disc: the rotor disc the blades sweep, solid with helicopter.collide_rotor.
  enum class Role { Body, Blade, Disc } role = Role::Body;
};

// The parts of a helicopter whose rotor has this radius.
std::vector<HelicopterPart> helicopterParts(float rotorRadius);

// The rotor hub in the room: over (x, y), altitude above the ground there.
glm::vec3 helicopterHub(const HelicopterSettings& s, const HeightMap* terrain);

// The parts the dust collides with while helicopter.enabled and
// helicopter.collide (the rotor disc also with collide_rotor), as obstacles
// that do not turn the flow (the helicopter's own wash is in the field).
std::vector<Obstacle> helicopterObstacles(const HelicopterSettings& s, float rotorRadius,
                                          const HeightMap* terrain);

}  // namespace sandstorm
