// MoleculeShape: a molecule's members at rest, the springs that hold them
// there and how it is drawn, for complexity 2..8 (MoleculeSettings):
//   2  a rod (one spring)
//   3  a triangle (three springs, one face)
//   4  a tetrahedron (six springs, four faces)
// The triangle and the tetrahedron are darts: the head stands kDartLength
// edges in front of a base of edge 1, so which way one points shows (a
// regular one looks the same from every side).
//   5..8  a chain: members one edge apart along a line, springs between
//      neighbours and, to keep it from folding, between every second member
// Member 0 is the head (MoleculeSettings::headMass); at rest the shape's
// members lie behind it along -x, so a molecule whose head leads points
// along its motion. Positions are in edge lengths (multiply by
// MoleculeSettings::size: the length of the base's edges, and a rod's or a
// chain's), centred on the members' mean.
// The GPU reads the same tables (contexts/molecules/molecule_block.h).
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

namespace sandstorm {

struct MoleculeSpring {
  int a = 0, b = 0;
  float rest = 1.0f;  // in edge lengths
};

inline constexpr float kDartLength = 2.5f;

struct MoleculeShape {
  static constexpr int kMaxSprings = 16;
  static constexpr int kMaxFaces = 4;

  int members = 0;
  std::vector<glm::vec3> rest;  // per member, in edge lengths
  std::vector<MoleculeSpring> springs;
  // Drawn as triangles (member indices; a closed shape's wind counter-clockwise
  // seen from outside), or, without faces, as ribbons along `lines`.
  std::vector<std::array<int, 3>> faces;
  std::vector<std::array<int, 2>> lines;
};

// The shape of that complexity; throws Error outside 2..8.
const MoleculeShape& moleculeShape(int complexity);

}  // namespace sandstorm
