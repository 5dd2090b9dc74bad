#version 450 core
// ParticleSplat, tiled variant, steps 2 (count) and 4 (scatter): workgroup g
// takes particles [g * perGroup, (g + 1) * perGroup) and finds the tiles each
// covers on its level's grid (splat_common.glsl), counting them in a
// histogram in shared memory, so a dense tile costs one global atomic a
// workgroup, not one a particle.
//   count (uScatter false): adds the histogram to the tiles' counts; what
//     each add returns is this workgroup's place in the tile's list (groupBase).
//     It also lists the particles it found in view (their indices, within
//     the workgroup's range of inView) and how many (inViewCount).
//   scatter (uScatter true): counts again, from tileStart + groupBase, and
//     writes each particle's splat record at the slot that gives. Where the
//     count listed at most half the workgroup's particles it visits only
//     those: a view sees a few of them, or none (a CAVE's side and back
//     walls), and reading all of them again cost as much as counting them.
//     Where the list is full (it holds uListCapacity records, two a
//     particle) the particle adds its footprint in that tile to the sums
//     itself, with global atomics (on the grid the tile's chunks would draw
//     it on): slower, the same integers. The listed order is the order the
//     count's invocations found them in, which varies, as the slots within a
//     tile's list already did: the sums are integers, so the image does not
//     depend on it.
//   A wall's two eyes (uNextList): the first eye's count also lists the
//     particles that may show in the second eye's view (nextView: the same
//     test with margins wider than any rounding, so a superset), and the
//     second eye's count visits only those where they are at most half the
//     workgroup's range. A CAVE's side walls and floor see a few percent of
//     the particles: their second eye no longer reads all of them.
//   Lists are written only up to half the range: a fuller one is never read.
// One program for both, so both passes find exactly the same tiles.
#include "view_block.glsl"
#include "render_block.glsl"
#include "splat_common.glsl"
#include "splat_footprint.glsl"

// Large workgroups: few of them fit an SM, so their histograms take little of
// its shared memory and leave the rest to the L1 cache (on an H200, 256
// invocations a workgroup took 2.6 times as long).
const uint kGroup = 1024u;
layout(local_size_x = 1024) in;
layout(std430, binding = 0) readonly restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 1) readonly restrict buffer VelocityKind { vec4 velocityKind[]; };
layout(std430, binding = 5) readonly buffer Dispatch {
  uvec4 dispatch;
  uint count;
  uvec4 binDispatch;
  uint perGroup;
} args;
layout(std430, binding = 7) restrict buffer TileCounts { uint tileCount[]; };
layout(std430, binding = 6) restrict buffer SplatAccumulation { uint accum[]; };
#ifdef MOTION_FILTER
layout(std430, binding = 16) restrict buffer SplatMotion { int motionSums[]; };
#endif
layout(std430, binding = 8) writeonly restrict buffer TileLists { uvec4 tileList[]; };  // splat records
layout(std430, binding = 9) readonly restrict buffer TileStarts { uint tileStart[]; };
layout(std430, binding = 10) restrict buffer GroupBase { uint groupBase[]; };  // [group][tile]
layout(std430, binding = 18) restrict buffer InView { uint inView[]; };            // particle indices
layout(std430, binding = 19) restrict buffer InViewCount { uint inViewCount[]; };  // [group]
// The wall's next view (the second eye), as view_block.glsl's.
layout(std140, binding = 7) uniform NextViewBlock {
  mat4 viewMatrix;
  mat4 projection;
  mat4 viewProjection;
  mat4 inverseViewProjection;
  vec4 eye;
  vec4 viewport;
} nextView;
// The particles that may show in the next view: a count a workgroup, then
// their indices within each workgroup's range.
layout(std430, binding = 20) restrict buffer NextInView {
  uint nextCount[kSplatMaxBinGroups];
  uint nextIndex[];
};
layout(location = 1) uniform bool uScatter;
layout(location = 2) uniform uint uListCapacity;
// 0: no next view; 1 (a count): list the particles that may show in
// nextView; 2 (a count): visit only the particles the first eye listed.
layout(location = 3) uniform int uNextList;

#include "splat_add.glsl"
#include "splat_coarsening.glsl"

shared uint sBins[kSplatMaxTiles];
// The count of the workgroup's particles in view: the histogram's last slot,
// which a view of fewer tiles never uses (the histogram fills the shared
// memory llvmpipe allows). A view of all kSplatMaxTiles tiles lists none,
// and its scatter visits every particle.
const uint kInViewSlot = kSplatMaxTiles - 1u;
// The count of those that may show in the next view (ParticleSplat lists
// them only for views of fewer tiles).
const uint kNextSlot = kSplatMaxTiles - 2u;

// Pixels beyond the next view's edges a particle's centre may lie and still
// be listed: more than a coarser level's rounding of its grid (up to 7
// pixels at the fourth level), the centre's fixed point and the float
// rounding between two programs; with MOTION_BLUR, its smear too.
#ifdef MOTION_BLUR
const float kNextMargin = 10.0 + kMaxSmear;
#else
const float kNextMargin = 10.0;
#endif

// Whether the particle at `center` may show in the next view: splatCentre
// and splatBounds's tests with its unclamped radius and a margin, so
// everything they pass passes this.
bool mayShowInNext(vec3 center) {
  vec4 clip = nextView.viewProjection * vec4(center, 1.0);
  if (!(clip.w > 0.5e-4)) return false;
  vec2 size = nextView.viewport.zw;
  vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * size;
  vec2 radius = 0.25 * look.params.x * vec2(nextView.projection[0][0], nextView.projection[1][1]) * size / clip.w;
  vec2 reach = radius + kNextMargin;
  return all(greaterThanEqual(pixel + reach, vec2(0.0))) && all(lessThanEqual(pixel - reach, size));
}

// Lists particle i in the workgroup's range of inView or nextIndex, counting
// it in sBins[slot]. Only while the count is at most half the range: a list
// fuller than that is never read, so once past half the count need only
// stay past it, and a particle that reads it there saves the atomic (in a
// view full of particles, every invocation of an SM adding to one word).
bool listOpen(uint slot, uint range) { return sBins[slot] * 2u <= range; }

void listParticle(uint slot, uint range, uint i, bool next) {
  if (!listOpen(slot, range)) return;
  uint at = atomicAdd(sBins[slot], 1u);
  if (at * 2u > range) return;
  if (next)
    nextIndex[gl_WorkGroupID.x * args.perGroup + at] = i;
  else
    inView[gl_WorkGroupID.x * args.perGroup + at] = i;
}

void main() {
  uint lid = gl_LocalInvocationIndex;
  ivec2 size = ivec2(view.viewport.zw);
  uint tiles = splatTileOffset(size, uSplatLevels);  // of every level
  uint group = gl_WorkGroupID.x;
  // Scatter: each tile's bin starts at this workgroup's first slot in the
  // tile's list (entries of tiles it has no particles in are never used).
  for (uint t = lid; t < tiles; t += kGroup)
    sBins[t] = uScatter ? tileStart[t] + groupBase[group * tiles + t] : 0u;
  bool listed = tiles <= kInViewSlot;
  bool listNext = !uScatter && uNextList == 1;
  if (listed && lid == 0u) sBins[kInViewSlot] = 0u;
  if (listNext && lid == 0u) sBins[kNextSlot] = 0u;
  barrier();
  uint begin = group * args.perGroup, end = min(begin + args.perGroup, args.count);
  uint range = end - begin;
  // Where most of the workgroup's particles are in view, reading them in
  // order beats gathering them through the list (the list's order is
  // scattered: 0.2 ms more a view at 10^8 on an H200).
  bool nextListed = !uScatter && uNextList == 2;
  uint listedCount = uScatter && listed ? inViewCount[group] : nextListed ? nextCount[group] : 0u;
  bool fromList = ((uScatter && listed) || nextListed) && listedCount * 2u <= range;
  uint visits = fromList ? listedCount : range;
  for (uint k = lid; k < visits; k += kGroup) {
    uint i = fromList ? (nextListed ? nextIndex[begin + k] : inView[begin + k]) : begin + k;
    // Counting needs only where the splat is (the positions; the velocities for motion blur).
    // The scatter's look word needs the velocity and lifetime too: read beside the
    // position, not after the view tests (0.05 ms less a front eye's scatter at
    // 10^8 on an H200, docs/PERFORMANCE.md).
    vec4 pl = positionLife[i];
#ifdef MOTION_BLUR
    vec4 vk = velocityKind[i];
#else
    vec4 vk = uScatter ? velocityKind[i] : vec4(0.0);
#endif
    // (Past half, the test is skipped too: most of a front wall's particles.)
    if (listNext && listOpen(kNextSlot, range) && mayShowInNext(pl.xyz))
      listParticle(kNextSlot, range, i, true);
    uvec3 where;
    Splat s;
#if defined(MOTION_BLUR)
    vec3 velocity = vk.xyz;
#elif defined(MOTION_FILTER)
    // The filter's splats are still: the motion only rides in the record.
    vec3 velocity = uScatter ? vk.xyz : vec3(0.0);
#else
    const vec3 velocity = vec3(0.0);
#endif
    if (!splatCentre(pl.xyz, velocity, where)) continue;
    int level = splatLevelOf(where);
    if (!splatBounds(where, level, s)) continue;
    if (!uScatter && listed) listParticle(kInViewSlot, range, i, false);
    uvec4 record = uvec4(where, uScatter ? splatLook(pl, vk) : 0u);
    ivec2 t0 = s.lo / kSplatTile, t1 = s.hi / kSplatTile;
    uint first = splatTileOffset(size, level), across = uint(splatLevelTiles(size, level).x);
    for (int ty = t0.y; ty <= t1.y; ++ty)
      for (int tx = t0.x; tx <= t1.x; ++tx) {
        uint tile = first + uint(ty) * across + uint(tx);
        uint slot = atomicAdd(sBins[tile], 1u);
        if (!uScatter) continue;
        if (slot < uListCapacity) {
          tileList[slot] = record;
        } else {
          // As the tile's chunks would: its motion on the tile's level, its
          // footprint on the grid the tile draws on (splatCoarsening).
          ivec2 origin = ivec2(tx, ty) * kSplatTile;
          uint records = tileStart[tile + 1u] - tileStart[tile];
          unpackSplat(record, level, s);
          addSplatMotion(s, max(s.lo, origin), min(s.hi, origin + kSplatTile - 1), splatMotionShift(records));
          int coarser = splatCoarsening(tile, level);
          ivec2 drawOrigin = origin >> coarser;
          if (unpackSplat(record, level + coarser, s))
            addSplatPixels(s, max(s.lo, drawOrigin), min(s.hi, drawOrigin + (kSplatTile >> coarser) - 1));
        }
      }
  }
  if (uScatter) return;
  barrier();
  if (listed && lid == 0u) inViewCount[group] = sBins[kInViewSlot];
  if (listNext && lid == 0u) nextCount[group] = sBins[kNextSlot];
  for (uint t = lid; t < tiles; t += kGroup) {
    uint n = sBins[t];
    if (n != 0u) groupBase[group * tiles + t] = atomicAdd(tileCount[t], n);
  }
}
