#version 450 core
// MoleculeGridGpu, step 1: each input molecule's centre (moleculeCentre: the
// members' mean), its cell's key and its index, for the stable sort by key.
#define ITEMS 1
#include "sim_block.glsl"
#include "molecule_block.glsl"
#include "particle_control.glsl"
#include "molecule_grid.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly restrict buffer InPositionLife { vec4 inPositionLife[]; };
layout(location = 0) uniform int uIn;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= ctl.count[uIn]) return;
  precise vec3 sum = vec3(0.0);
  for (int j = 0; j < molecule.shape.x; ++j)
    sum = sum + inPositionLife[moleculeRecord(i, j)].xyz;
  precise vec3 centre = sum * molecule.motion.w;
  gridCentres[i] = vec4(centre, 0.0);
  gridKeys[i] = gridKey(gridCell(centre));
  gridValues[i] = i;
}
