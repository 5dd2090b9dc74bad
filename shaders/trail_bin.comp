#version 450 core
// ParticleSplat, tiled trails, steps 2 (stage) and 4 (place), as
// splat_bin.comp bins splats: workgroup g takes the trails of particles
// [g * perGroup, (g + 1) * perGroup), walks each pixel by pixel
// (trail_common.glsl) and cuts it into runs of consecutive pixels in one
// 32x32 tile of the view.
//   stage (uPlace false): the one walk. Each run gets its rank among this
//     workgroup's runs in its tile (a histogram of the tiles in shared
//     memory) and is staged, with its tile and rank, in the workgroup's
//     share of the staging buffer; the histogram is added to the tiles'
//     counts, and what each add returns is this workgroup's place in the
//     tile's list. A run past the workgroup's share adds its pixels itself
//     with global atomics (the same integers, slower).
//   place (uPlace true, after the scan): copies each staged run to its
//     place in its tile's list; where the list is full the run adds its
//     pixels itself, as above.
// Staging spares a second walk: on an H100 the walk, not the memory it
// reads, is what a pass costs (a trail made up of its particle's velocity
// instead of read from the ring took as long).
// A run costs its tile one record however many segments it spans: a trail
// of a few pixels a segment makes a few runs, not one a segment.
#include "view_block.glsl"
#include "render_block.glsl"
#include "splat_common.glsl"

const uint kGroup = 1024u;  // as splat_bin.comp's
layout(local_size_x = 1024) in;
layout(std430, binding = 5) readonly buffer Dispatch {
  uvec4 dispatch;
  uint count;
  uvec4 binDispatch;
  uint perGroup;
} args;
layout(std430, binding = 6) restrict buffer SplatAccumulation { uint accum[]; };
layout(std430, binding = 7) restrict buffer TileCounts { uint tileCount[]; };
layout(std430, binding = 8) writeonly restrict buffer TileLists { uvec2 runs[]; };
layout(std430, binding = 9) readonly restrict buffer TileStarts { uint tileStart[]; };
layout(std430, binding = 10) restrict buffer GroupBase { uint groupBase[]; };  // [group][tile]
// A workgroup's share of uStageCapacity records, then each workgroup's count.
// A staged run is three words: the run's two, and its tile | rank << 13.
layout(std430, binding = 17) restrict buffer Staged { uint staged[]; };
layout(location = 1) uniform bool uPlace;
layout(location = 2) uniform uint uListCapacity;   // runs
layout(location = 3) uniform uint uStageCapacity;  // staged runs, all workgroups'

#include "trail_common.glsl"

// Two tiles' counts a word, 16 bits each (a share is at most 65535 runs):
// with the staged count, a full histogram takes 16 KB of shared memory,
// within llvmpipe's 32 KB.
shared uint sBins[kSplatMaxTiles / 2u];
shared uint sStaged;

const uint kRankShift = 13u;    // kSplatMaxTiles is 2^13
const uint kMaxShare = 65535u;  // so that a tile's count fits its 16 bits

// Adds one to tile t's count; returns the count before.
uint binAdd(uint t) {
  uint shift = (t & 1u) * 16u;
  return (atomicAdd(sBins[t >> 1], 1u << shift) >> shift) & 0xffffu;
}
uint binCount(uint t) { return (sBins[t >> 1] >> ((t & 1u) * 16u)) & 0xffffu; }

void trailAdd(ivec2 p, ivec2 origin, uint v[kSplatTrailChannels]) {
  uint base = (uint(p.y) * uint(view.viewport.z) + uint(p.x)) * kSplatStride + kSplatTrailChannel;
  atomicAdd(accum[base], v[0]);
  atomicAdd(accum[base + 1u], v[1]);
}

ivec2 tileOrigin(uint tile, uint across) { return ivec2(int(tile % across), int(tile / across)) * kSplatTile; }

uint share() { return min(uStageCapacity / gl_NumWorkGroups.x, kMaxShare); }
// Where the workgroups' counts of staged runs follow the runs.
uint counts() { return gl_NumWorkGroups.x * share() * 3u; }

void stageRun(uint o, uint tile, uint first, uint last, uint across) {
  uint k = atomicAdd(sStaged, 1u);
  uvec2 run = uvec2(o, first | (last << 16));
  if (k >= share()) {
    trailRun(o, first, last, tileOrigin(tile, across));  // global atomics
    return;
  }
  uint rank = binAdd(tile);
  uint at = (gl_WorkGroupID.x * share() + k) * 3u;
  staged[at] = run.x;
  staged[at + 1u] = run.y;
  staged[at + 2u] = tile | (rank << kRankShift);
}

// The tile of a pixel, -1 off screen.
int tileOf(ivec2 p, uint across) {
  return trailOnScreen(p) ? (p.y / kSplatTile) * int(across) + p.x / kSplatTile : -1;
}

void stage(uint begin, uint end, uint across) {
  for (uint o = begin + gl_LocalInvocationIndex; o < end; o += kGroup) {
    int run = -1;  // the tile of the run being walked
    uint first = 0u, last = 0u;
    TrailPoint newer = trailPoint(o, 0);
    for (int j = 0; j < uTrailLength - 1; ++j) {
      TrailPoint older = trailPoint(o, j + 1);
      TrailSegment s;
      bool drawn = trailSegment(newer, older, j, s);
      newer = older;
      if (!drawn) continue;
      // A segment's pixels move monotonically along each axis, so where its
      // first and last are in one tile on screen, so are all between.
      int firstTile = tileOf(trailPixel(s, 0), across), lastTile = tileOf(trailPixel(s, s.n - 1), across);
      bool oneTile = firstTile >= 0 && firstTile == lastTile;
      for (int step = 0; step < s.n; step = oneTile ? s.n : step + 1) {
        int tile = oneTile ? firstTile : tileOf(trailPixel(s, step), across);
        uint at = uint(j * kTrailMaxPixels + step);
        if (tile != run) {
          if (run >= 0) stageRun(o, uint(run), first, last, across);
          run = tile;
          first = at;
        }
        last = oneTile ? uint(j * kTrailMaxPixels + s.n - 1) : at;
      }
    }
    if (run >= 0) stageRun(o, uint(run), first, last, across);
  }
}

void place(uint tiles, uint across) {
  uint group = gl_WorkGroupID.x, n = min(staged[counts() + group], share());
  for (uint k = gl_LocalInvocationIndex; k < n; k += kGroup) {
    uint at = (group * share() + k) * 3u;
    uvec3 r = uvec3(staged[at], staged[at + 1u], staged[at + 2u]);
    uint tile = r.z & ((1u << kRankShift) - 1u);
    uint slot = tileStart[tile] + groupBase[group * tiles + tile] + (r.z >> kRankShift);
    if (slot < uListCapacity)
      runs[slot] = r.xy;
    else
      trailRun(r.x, r.y & 0xffffu, r.y >> 16, tileOrigin(tile, across));  // global atomics
  }
}

void main() {
  uint lid = gl_LocalInvocationIndex;
  ivec2 size = ivec2(view.viewport.zw);
  uint tiles = splatTileOffset(size, 1), across = uint(splatLevelTiles(size, 0).x);
  uint group = gl_WorkGroupID.x;
  if (uPlace) {
    place(tiles, across);
    return;
  }
  for (uint t = lid; t < (tiles + 1u) / 2u; t += kGroup) sBins[t] = 0u;
  if (lid == 0u) sStaged = 0u;
  barrier();
  uint begin = group * args.perGroup;
  stage(begin, min(begin + args.perGroup, args.count), across);
  barrier();
  if (lid == 0u) staged[counts() + group] = sStaged;
  for (uint t = lid; t < tiles; t += kGroup) {
    uint n = binCount(t);
    if (n != 0u) groupBase[group * tiles + t] = atomicAdd(tileCount[t], n);
  }
}
