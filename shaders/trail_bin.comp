#version 450 core
// ParticleSplat, tiled trails, steps 2 (count) and 4 (scatter), as
// splat_bin.comp does for splats: workgroup g takes the trails of particles
// [g * perGroup, (g + 1) * perGroup), walks each pixel by pixel
// (trail_common.glsl) and cuts it into runs of consecutive pixels in one
// 32x32 tile of the view, counting the runs in a histogram of the tiles in
// shared memory.
//   count (uScatter false): adds the histogram to the tiles' counts; what
//     each add returns is this workgroup's place in the tile's list.
//   scatter (uScatter true): counts again and writes each run's record (the
//     particle, its first and last pixel) in its tile's list; where the list
//     is full the run adds its pixels itself with global atomics (the same
//     integers, slower).
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
layout(location = 1) uniform bool uScatter;
layout(location = 2) uniform uint uListCapacity;  // runs

#include "trail_common.glsl"

shared uint sBins[kSplatMaxTiles];

void trailAdd(ivec2 p, ivec2 origin, uint v[kSplatTrailChannels]) {
  uint base = (uint(p.y) * uint(view.viewport.z) + uint(p.x)) * kSplatStride + kSplatTrailChannel;
  atomicAdd(accum[base], v[0]);
  atomicAdd(accum[base + 1u], v[1]);
}

void binRun(uint o, uint tile, uint first, uint last, uint across) {
  uint slot = atomicAdd(sBins[tile], 1u);
  if (!uScatter) return;
  if (slot < uListCapacity)
    runs[slot] = uvec2(o, first | (last << 16));
  else
    trailRun(o, first, last, ivec2(int(tile % across), int(tile / across)) * kSplatTile);
}

// The tile of a pixel, -1 off screen.
int tileOf(ivec2 p, uint across) {
  return trailOnScreen(p) ? (p.y / kSplatTile) * int(across) + p.x / kSplatTile : -1;
}

void main() {
  uint lid = gl_LocalInvocationIndex;
  ivec2 size = ivec2(view.viewport.zw);
  uint tiles = splatTileOffset(size, 1), across = uint(splatLevelTiles(size, 0).x);
  uint group = gl_WorkGroupID.x;
  for (uint t = lid; t < tiles; t += kGroup)
    sBins[t] = uScatter ? tileStart[t] + groupBase[group * tiles + t] : 0u;
  barrier();
  uint begin = group * args.perGroup, end = min(begin + args.perGroup, args.count);
  for (uint o = begin + lid; o < end; o += kGroup) {
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
          if (run >= 0) binRun(o, uint(run), first, last, across);
          run = tile;
          first = at;
        }
        last = oneTile ? uint(j * kTrailMaxPixels + s.n - 1) : at;
      }
    }
    if (run >= 0) binRun(o, uint(run), first, last, across);
  }
  if (uScatter) return;
  barrier();
  for (uint t = lid; t < tiles; t += kGroup) {
    uint n = sBins[t];
    if (n != 0u) groupBase[group * tiles + t] = atomicAdd(tileCount[t], n);
  }
}
