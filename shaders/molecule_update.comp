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
#include "molecule_physics.glsl"

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

void loadMolecule(uint i, out Particle m[kMoleculeMaxMembers]) {
  uint n = uint(molecule.shape.x);
  for (uint j = 0u; j < n; ++j) {
    m[j].positionLife = inPositionLife[i * n + j];
    m[j].velocityKind = inVelocityKind[i * n + j];
  }
}

vec3 repulsionOf(uint i) {
#ifdef REPULSION
  return gridDisplacement(i);
#else
  return vec3(0.0);
#endif
}

bool survives(uint i) {
  Particle m[kMoleculeMaxMembers];
  loadMolecule(i, m);
  return advanceMolecule(m, repulsionOf(i));
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
  Particle m[kMoleculeMaxMembers];
  bool alive = false;
  if (i < inCount) {
    loadMolecule(i, m);
    alive = advanceMolecule(m, repulsionOf(i));
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
    ctl.draw[1 - uIn] = uvec4(uVertices, live, 0u, 0u);
  }
  uint o = uBorn + prefix + before;
  if (alive && o < uCapacity) {
    uint n = uint(molecule.shape.x);
    for (uint j = 0u; j < n; ++j) {
      outPositionLife[o * n + j] = m[j].positionLife;
      outVelocityKind[o * n + j] = m[j].velocityKind;
    }
  }
}
