#version 450 core
// MoleculeUpdate, step 3: every input molecule steps (advanceMolecule, one an
// invocation, its members in registers); the survivors are written whole
// after the newborn, in their input order, by the particle update's
// order-keeping compaction (tiles of 256 molecules, tile_lookback.glsl).
// REPULSION programs read the repulsion grid MoleculeGridGpu built from the
// input molecules' centres (its sums twin MoleculeGrid::displacement).
#define MOLECULES
#define ITEMS 1
#include "rng.glsl"
#include "sim_block.glsl"
#include "molecule_block.glsl"
#include "particle_physics.glsl"
#include "particle_control.glsl"
#include "molecule_birth.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly restrict buffer InPositionLife { vec4 inPositionLife[]; };
layout(std430, binding = 1) readonly restrict buffer InVelocityKind { vec4 inVelocityKind[]; };
layout(std430, binding = 2) writeonly restrict buffer OutPositionLife { vec4 outPositionLife[]; };
layout(std430, binding = 3) writeonly restrict buffer OutVelocityKind { vec4 outVelocityKind[]; };
layout(std430, binding = 5) coherent volatile restrict buffer TileStatus { uint status[]; };

layout(location = 0) uniform int uIn;
layout(location = 1) uniform uint uBorn;      // newborn molecules
layout(location = 2) uniform uint uCapacity;  // molecules
layout(location = 3) uniform uint uSpinLimit;
layout(location = 5) uniform uint uVertices;  // a molecule draws
#ifdef REPULSION
#define GRID_READ
#include "molecule_grid.glsl"
#endif

// The molecule advanceMolecule is stepping: memberStart() reads its input.
uint gMolecule = 0u;

vec3 memberStart(int j) {
  return inPositionLife[moleculeRecord(gMolecule, j)].xyz;
}

#include "molecule_physics.glsl"

// Loads molecule i; returns its life and lifetime (its members share them).
vec2 loadMolecule(uint i, out vec3 x[kMembers], out vec3 v[kMembers]) {
  gMolecule = i;
  vec4 head = inPositionLife[i];
  vec4 headVelocity = inVelocityKind[i];
  vec2 life = vec2(head.w, headVelocity.w);
  x[0] = head.xyz;
  v[0] = headVelocity.xyz;
  for (int j = 1; j < kMembers; ++j) {
    x[j] = inPositionLife[moleculeRecord(i, j)].xyz;
    v[j] = inVelocityKind[moleculeRecord(i, j)].xyz;
  }
  return life;
}

vec3 repulsionOf(uint i) {
#ifdef REPULSION
  return gridDisplacement(i);
#else
  return vec3(0.0);
#endif
}

bool survives(uint i) {
  vec3 x[kMembers], v[kMembers];
  vec2 life = loadMolecule(i, x, v);
  return advanceMolecule(x, v, life.x, life.y, repulsionOf(i));
}

#include "tile_lookback.glsl"

shared uint sTicket;
shared uint sScan[256];

void main() {
  uint lid = gl_LocalInvocationIndex;
  if (lid == 0u) sTicket = atomicAdd(ctl.ticket, 1u);
  barrier();
  uint tile = sTicket;
  uint tiles = ctl.tiles;
  if (tile >= tiles) return;  // the whole workgroup: a spare of the 2D dispatch
  uint inCount = ctl.count[uIn];

  uint i = tile * kTile + lid;
  vec3 x[kMembers], v[kMembers];
  vec2 life = vec2(0.0);
  bool alive = false;
  if (i < inCount) {
    life = loadMolecule(i, x, v);
    alive = advanceMolecule(x, v, life.x, life.y, repulsionOf(i));
  }
  uint mine = alive ? 1u : 0u;
  sScan[lid] = mine;
  barrier();
  for (uint offset = 1u; offset < 256u; offset <<= 1u) {
    uint add = lid >= offset ? sScan[lid - offset] : 0u;
    barrier();
    sScan[lid] += add;
    barrier();
  }
  uint before = sScan[lid] - mine;
  uint aggregate = sScan[255];
  barrier();

  uint prefix = lookBack(tile, aggregate, inCount);
  if (lid == 0u && tile == tiles - 1u) {
    uint live = min(uBorn + prefix + aggregate, uCapacity);
    ctl.count[1 - uIn] = live;
    ctl.draw[1 - uIn] = uvec4(uVertices * live, 1u, 0u, 0u);
  }
  uint o = uBorn + prefix + before;
  if (alive && o < uCapacity) {
    for (int j = 0; j < kMembers; ++j) {
      outPositionLife[moleculeRecord(o, j)] = vec4(x[j], life.x);
      outVelocityKind[moleculeRecord(o, j)] = vec4(v[j], life.y);
    }
  }
}
