#version 450 core
// MoleculeUpdate, step 2: invocation g writes the g-th newborn molecule of the
// update, members at records moleculeRecord(g, j) (birthMolecule, then
// settleNewbornMolecule); emitters' newborn follow one another in emitter
// order, as particles' do (particle_emit.comp). The sim block's granted
// counts are the molecule emitters'.
#define MOLECULES
#include "rng.glsl"
#include "sim_block.glsl"
#include "molecule_block.glsl"
#include "particle_birth.glsl"
#include "terrain_height.glsl"
#ifdef OBSTACLES
#include "obstacles.glsl"
#endif
#include "molecule_birth.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 2) writeonly restrict buffer OutPositionLife { vec4 outPositionLife[]; };
layout(std430, binding = 3) writeonly restrict buffer OutVelocityKind { vec4 outVelocityKind[]; };
layout(location = 1) uniform uint uBorn;

void main() {
  uint g = gl_GlobalInvocationID.x;
  if (g >= uBorn) return;
  int count = int(sim.frameSeed.w);
  int e = 0;
  uint first = 0u;
  while (e + 1 < count && g >= first + uint(sim.emitters[e].shapeCount.y)) {
    first += uint(sim.emitters[e].shapeCount.y);
    ++e;
  }
  uint k = g - first;
  Particle centre = birth(e, k);
  vec4 q = randomTurn(sim.frameSeed.yz, sim.frameSeed.x, uint(e), k);
  int n = molecule.shape.x;
  Particle m[kMoleculeMaxMembers];
  for (int j = 0; j < n; ++j)
    m[j] = birthMember(q, centre, j);
  settleNewbornMolecule(m);
  for (int j = 0; j < n; ++j) {
    outPositionLife[moleculeRecord(g, j)] = m[j].positionLife;
    outVelocityKind[moleculeRecord(g, j)] = m[j].velocityKind;
  }
}
