#version 450 core
// MoleculeGridGpu, step 3 (after the sort): where each key's run of sorted
// molecules starts (the table was cleared to "none").
#define ITEMS 1
#include "sim_block.glsl"
#include "molecule_block.glsl"
#include "particle_control.glsl"
#include "molecule_grid.glsl"

layout(local_size_x = 256) in;
layout(location = 0) uniform int uIn;

void main() {
  uint s = gl_GlobalInvocationID.x;
  if (s >= ctl.count[uIn]) return;
  uint key = gridKeys[s];
  if (s == 0u || gridKeys[s - 1u] != key) gridStarts[key] = s;
}
