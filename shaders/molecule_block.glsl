// The molecules' uniform block: the twin of contexts/molecules/molecule_block.h,
// filled from MoleculeParams and MoleculeShape (core/molecules).
const int kMoleculeMaxMembers = 8;
const int kMoleculeMaxSprings = 16;

layout(std140, binding = 5) uniform MoleculeBlock {
  ivec4 shape;       // members, iterations, springs, 1 for a solid shape (faces)
  vec4 mass;         // head mass, 1 / head mass, 1 / total mass, pass stiffness
  vec4 motion;       // damping, 1 / dt, size (m), 1 / members
  vec4 push;         // the push tool's centre, w: its radius
  vec4 pushMore;     // x: its speed, y: 1 when on, z: 1 / (members - 1)
  vec4 repulsion;    // x: 1 when on, y: radius, z: 1 / radius, w: each one's share
  uvec4 grid;        // x: the repulsion table's size - 1 (a power of two), y: the buffers' capacity (molecules)
  vec4 springs[kMoleculeMaxSprings];  // member a, member b, rest length (m), pass share / (w_a + w_b)
  vec4 rest[kMoleculeMaxMembers];     // rest position (edges), w: the vane's reach
  ivec4 faces[4];    // drawn triangles' members
  ivec4 lines[8];    // drawn ribbons' members (shapes without faces)
  ivec4 drawing;     // x: faces, y: lines, z: vertices a molecule draws
  vec4 look;         // x: ribbon width (m)
} molecule;

// Member j of molecule i is record j * capacity + i: member by member, so
// neighbouring invocations (molecules) read and write neighbouring records.
uint moleculeRecord(uint i, int j) {
  return uint(j) * molecule.grid.y + i;
}
