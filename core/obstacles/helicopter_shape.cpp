#include "core/obstacles/helicopter_shape.h"

namespace sandstorm {

std::vector<HelicopterPart> helicopterParts(float r) {
  const glm::vec3 body(0.22f, 0.25f, 0.2f), metal(0.1f), blade(0.08f);
  using S = ObstacleShape;
  using R = HelicopterPart::Role;
  return {
      {S::Box, {0.1f * r, 0.0f, -0.33f * r}, {1.6f * r, 0.34f * r, 0.32f * r}, body, R::Body},
      {S::Box, {-1.2f * r, 0.0f, -0.2f * r}, {1.5f * r, 0.08f * r, 0.1f * r}, body, R::Body},
      {S::Box, {-1.9f * r, 0.0f, -0.05f * r}, {0.12f * r, 0.04f * r, 0.35f * r}, body, R::Body},
      {S::Box, {0.0f, 0.0f, -0.08f * r}, {0.05f * r, 0.05f * r, 0.16f * r}, metal, R::Body},
      {S::Box, {0.0f, 0.0f, 0.0f}, {2.0f * r, 0.07f * r, 0.015f * r}, blade, R::Blade},
      {S::Box, {0.0f, 0.0f, 0.0f}, {0.07f * r, 2.0f * r, 0.015f * r}, blade, R::Blade},
      {S::Cylinder, {0.0f, 0.0f, 0.0f}, {2.0f * r, 2.0f * r, 0.015f * r}, blade, R::Disc},
  };  // fuselage, tail boom, fin, mast, two blades, the disc they sweep
}

glm::vec3 helicopterHub(const HelicopterSettings& s, const HeightMap* terrain) {
  const float ground = terrain ? terrain->heightAt({s.x, s.y}) : 0.0f;
  return {s.x, s.y, ground + s.altitude};
}

std::vector<Obstacle> helicopterObstacles(const HelicopterSettings& s, float rotorRadius,
                                          const HeightMap* terrain) {
  std::vector<Obstacle> out;
  if (!s.enabled || !s.collide) return out;
  const glm::vec3 hub = helicopterHub(s, terrain);
  for (const HelicopterPart& part : helicopterParts(rotorRadius)) {
    if (part.role == HelicopterPart::Role::Blade) continue;
    if (part.role == HelicopterPart::Role::Disc && !s.collideRotor) continue;
    Obstacle o;
    o.shape = part.shape;
    o.position = hub + part.center;
    o.size = part.size;
    o.radius = 0.5f * part.size.x;
    o.height = part.size.z;
    o.flow = false;
    o.restitution = 0.3f;
    out.push_back(o);
  }
  return out;
}

}  // namespace sandstorm
