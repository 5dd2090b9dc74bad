#version 450 core
// ParticleComputeUpdate, step 3: every input record ages and moves (advance(),
// the same function as the transform-feedback path's particle_update.geom);
// the survivors are written after the newborn in their input order.
//
// Order-preserving compaction by a single-pass prefix sum with decoupled
// look-back (tile_lookback.glsl): a workgroup takes its tile index from an
// atomic ticket, so tile t starts only after tiles 0..t-1 have started and
// waiting on them cannot deadlock; it scans its own survivors in shared
// memory, looks back for its predecessors' count and writes its survivors.
#include "sim_block.glsl"
#include "particle_physics.glsl"
#include "particle_control.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly restrict buffer InPositionLife { vec4 inPositionLife[]; };
layout(std430, binding = 1) readonly restrict buffer InVelocityKind { vec4 inVelocityKind[]; };
layout(std430, binding = 2) writeonly restrict buffer OutPositionLife { vec4 outPositionLife[]; };
layout(std430, binding = 3) writeonly restrict buffer OutVelocityKind { vec4 outVelocityKind[]; };
layout(std430, binding = 5) coherent volatile restrict buffer TileStatus { uint status[]; };
// Trails (ParticleTrails): each survivor's input record, so its trail can follow it.
layout(std430, binding = 6) writeonly restrict buffer TrailSource { uint trailSource[]; };

#ifdef OBSTACLE_LIST
// The survivors not clear of every obstacle (their output records), for
// obstacle_collide.comp to put out: the only records that pass reads.
layout(std430, binding = 8) restrict buffer CollideList { uint collideCount; uint collideIndex[]; };
#endif

layout(location = 0) uniform int uIn;
layout(location = 1) uniform uint uBorn;
layout(location = 2) uniform uint uCapacity;
layout(location = 3) uniform uint uSpinLimit;  // reads of a predecessor's status before counting it here
layout(location = 4) uniform bool uTrails;     // write trailSource

// Whether input record i survives this update (the look-back's recount).
bool survives(uint i) {
#ifdef BARE_UPDATE
  return true;  // sandstorm-bench's ceiling: the same data movement and scan, no physics
#else
  Particle q;
  q.positionLife = inPositionLife[i];
  q.velocityKind = inVelocityKind[i];
  return advance(q);
#endif
}

#include "tile_lookback.glsl"

shared uint sTicket;
#if ITEMS > 4
shared uvec4 sScan[256];
#else
shared uvec2 sScan[256];
#endif

void main() {
  uint lid = gl_LocalInvocationIndex;
  if (lid == 0u) sTicket = atomicAdd(ctl.ticket, 1u);
  barrier();
  uint tile = sTicket;
  uint tiles = ctl.tiles;
  if (tile >= tiles) return;  // the whole workgroup: a spare of the 2D dispatch
  uint inCount = ctl.count[uIn];

  // Record k * 256 + lid of the tile: neighbouring invocations read neighbouring records.
  Particle p[kItems];
  bool alive[kItems];
  for (int k = 0; k < kItems; ++k) {
    uint i = tile * kTile + uint(k) * 256u + lid;
    alive[k] = false;
    if (i < inCount) {
      p[k].positionLife = inPositionLife[i];
      p[k].velocityKind = inVelocityKind[i];
#ifdef BARE_UPDATE
      alive[k] = true;  // sandstorm-bench's ceiling: the same data movement and scan, no physics
#else
      alive[k] = advance(p[k]);
#endif
    }
  }

  // Inclusive scan over the invocations of the rows' survivor flags (row k:
  // records k * 256 .. k * 256 + 255 of the tile), two 16-bit counters per
  // word (a row has at most 256 survivors).
  // (Four records, the default, scan two words an invocation; eight, four.
  // On an H200 the narrower scan left the update 20% faster.)
#if ITEMS > 4
  uvec4 mine = uvec4(0u);
#else
  uvec2 mine = uvec2(0u);
#endif
  for (int k = 0; k < kItems; ++k)
    if (alive[k]) mine[k / 2] += (k % 2 == 0) ? 1u : 0x10000u;
  sScan[lid] = mine;
  barrier();
  for (uint offset = 1u; offset < 256u; offset <<= 1u) {
#if ITEMS > 4
    uvec4 add = lid >= offset ? sScan[lid - offset] : uvec4(0u);
#else
    uvec2 add = lid >= offset ? sScan[lid - offset] : uvec2(0u);
#endif
    barrier();
    sScan[lid] += add;
    barrier();
  }
#if ITEMS > 4
  uvec4 before = sScan[lid] - mine;
  uvec4 total = sScan[255];
#else
  uvec2 before = sScan[lid] - mine;
  uvec2 total = sScan[255];
#endif
  uint rowStart[kItems];
  uint aggregate = 0u;
  for (int k = 0; k < kItems; ++k) {
    rowStart[k] = aggregate;
    aggregate += (total[k / 2] >> (16u * uint(k % 2))) & 0xffffu;
  }

  uint prefix = lookBack(tile, aggregate, inCount);
  if (lid == 0u && tile == tiles - 1u) {
    uint live = min(uBorn + prefix + aggregate, uCapacity);
    ctl.count[1 - uIn] = live;
    ctl.draw[1 - uIn] = uvec4(live, 1u, 0u, 0u);
  }

  uint base = uBorn + prefix;
  for (int k = 0; k < kItems; ++k) {
    uint o = base + rowStart[k] + ((before[k / 2] >> (16u * uint(k % 2))) & 0xffffu);
    if (alive[k] && o < uCapacity) {
      outPositionLife[o] = p[k].positionLife;
      outVelocityKind[o] = p[k].velocityKind;
      if (uTrails) trailSource[o] = tile * kTile + uint(k) * 256u + lid;
#ifdef OBSTACLE_LIST
      bool clear = true;
      for (int i = 0; i < sim.obstacleCount.x; ++i)
        clear = clear && clearOf(i, p[k].positionLife.xyz);
      if (!clear) collideIndex[atomicAdd(collideCount, 1u)] = o;
#endif
    }
  }
}
