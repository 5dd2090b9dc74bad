#version 450 core
// ParticleComputeUpdate (and MoleculeUpdate, MOLECULES), step 1: one invocation sizes the update from the
// input's live count (known only to the GPU) and starts the output with its
// newborn, so a set with no input still ends the update with the right count.
#include "particle_control.glsl"

layout(local_size_x = 1) in;
layout(location = 0) uniform int uIn;    // the input set; the output is 1 - uIn
layout(location = 1) uniform uint uBorn; // newborn of this update
#ifdef MOLECULES
layout(location = 2) uniform uint uVertices;  // a molecule's: the draw covers every molecule's
#endif

void main() {
  uint inCount = ctl.count[uIn];
  int outSet = 1 - uIn;
  ctl.count[outSet] = uBorn;
#ifdef MOLECULES
  ctl.draw[outSet] = uvec4(uVertices * uBorn, 1u, 0u, 0u);
#else
  ctl.draw[outSet] = uvec4(uBorn, 1u, 0u, 0u);
#endif
  uint tiles = (inCount + kTile - 1u) / kTile;
  ctl.ticket = 0u;
  ctl.tiles = tiles;
  uint x = min(tiles, kGroupsPerRow);
  uint y = tiles == 0u ? 0u : (tiles + kGroupsPerRow - 1u) / kGroupsPerRow;
  ctl.dispatch = uvec4(x, y, 1u, 0u);
}
