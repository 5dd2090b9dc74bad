// helicopterModel: the downdraft demo's helicopter as the scene draws it, a
// procedural mesh built here rather than downloaded: a rounded fuselage with
// its cockpit glazing and engine cowling, a tapered tail boom, fin and
// stabiliser, skids on struts, the mast and hub, and the two rotors as the
// translucent discs their spinning blades blur into. The rotor's hub is the
// origin, x forward (the boom runs aft, -x), z up, sized by the rotor's
// radius. Fuselage, cowling, glazing, boom and fin lie within the solid boxes
// the dust collides with (core/obstacles/helicopter_shape.h); the skids, the
// stabiliser and the rotors are too thin to stop it and are drawn only.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sandstorm {

struct ModelVertex {
  glm::vec3 position;
  glm::vec3 normal;  // unit, outward
};

struct ModelPart {
  std::string name;
  glm::vec4 color;                     // alpha < 1: translucent (drawn after the opaque scene)
  std::vector<ModelVertex> triangles;  // three vertices a triangle, counter-clockwise outside
};

std::vector<ModelPart> helicopterModel(float rotorRadius);

}  // namespace sandstorm
