// MoleculeSettings: the molecules' attributes (molecule.* in the table of
// dynamic attributes, [molecules] in a configuration, the menu's Molecules
// section). A molecule (the molecules paper, ../shared/seeds/) is a small
// mass-spring mesh of 2 to 8 particles that an emitter of kind "molecules"
// emits and the update kills whole; core/molecules/molecule_physics.h says
// how it moves.
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

struct MoleculeSettings {
  static constexpr int kMinComplexity = 2, kMaxComplexity = 8;

  int maximum = 20000;     // soft limit on live molecules (run.molecule_capacity is the hard one)
  int complexity = 4;      // members: 2 a rod, 3 a triangle, 4 a tetrahedron, 5..8 a chain
  float size = 0.08f;      // m: the rest length of the shape's edges
  float stiffness = 0.8f;  // share of the springs' stretch a step removes
  float damping = 0.2f;    // share of the members' motion against the molecule's a step removes
  int iterations = 4;      // spring restoration passes a step
  float headMass = 4.0f;   // member 0's mass (the others weigh 1)
  float vane = 0.2f;       // how much more of the flow the tail feels than the head (0: none)
  bool repulsion = false;  // molecules whose centres come closer than the radius push apart
  float repulsionRadius = 0.1f;    // m
  float repulsionStrength = 0.5f;  // share of the overlap a step removes
  float width = 0.012f;            // m: drawn width of rods and chains
  // The push tool: a gust blowing outward from a point (the wand's tip or the
  // mouse's point), felt by molecules within the radius.
  bool push = false;
  bool pushTool = false;  // the left mouse button and the wand's grab button push (app/molecule_push)
  glm::vec3 pushPosition{0.0f};
  float pushRadius = 1.0f;  // m
  float pushSpeed = 4.0f;   // m/s at the point, falling to 0 at the radius
};

}  // namespace sandstorm
