#version 450 core
// ParticleSplat, tiled variant, step 5: one workgroup a chunk (at most
// uChunk splat records of one tile's list, a tile of one level's grid;
// records past the list's capacity were added by the scatter pass). Its
// splats add to the tile's sums in shared memory; then the workgroup adds
// those to the view's sums (the buffer the resolve pass turns into the
// image): a plain store where the chunk is its tile's only one, a global
// atomic where a dense tile has several. The same integers as the atomic
// variant adds, so the same image, with at most six global atomics a pixel
// and chunk instead of six a pixel and particle. A dense tile
// (render.splat_overlap: splatCoarsening) draws its splats on a coarser
// level's grid instead, into the block of that level's pixels its own pixels
// lie in: the same sums sampled more coarsely, added with atomics (that
// level's own tiles add there too).
#include "view_block.glsl"
#include "render_block.glsl"
#include "splat_common.glsl"
#include "splat_footprint.glsl"

// 512 invocations: as in splat_bin.comp, fewer workgroups an SM leave more
// of its memory to the L1 cache (256 took 1.5 times as long on an H200).
const uint kGroup = 512u;
layout(local_size_x = 512) in;
layout(std430, binding = 6) restrict buffer SplatAccumulation { uint accum[]; };
layout(std430, binding = 8) readonly restrict buffer TileLists { uvec4 tileList[]; };
layout(std430, binding = 9) readonly restrict buffer TileStarts { uint tileStart[]; };
layout(std430, binding = 11) readonly restrict buffer ChunkStarts { uint chunkStart[]; };
layout(std430, binding = 12) readonly buffer ChunkDispatch {
  uvec4 dispatch;
  uint chunks;
} chunkArgs;
layout(location = 1) uniform uint uChunk;  // entries a chunk
layout(location = 2) uniform uint uListCapacity;
#ifdef MOTION_FILTER
layout(std430, binding = 16) restrict buffer SplatMotion { int motionSums[]; };  // a tile's: splat_common.glsl
#endif

#include "splat_occupied.glsl"
#include "splat_coarsening.glsl"

const uint kTilePixels = uint(kSplatTile * kSplatTile);
shared uint sSums[kSplatChannels][kTilePixels];

void main() {
  uint chunk = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  if (chunk >= chunkArgs.chunks) return;  // the whole workgroup
  // The chunk's tile: the last tile whose chunks start at or before it.
  ivec2 size = ivec2(view.viewport.zw);
  uint lo = 0u, hi = splatTileOffset(size, uSplatLevels);
  while (hi - lo > 1u) {
    uint mid = (lo + hi) / 2u;
    if (chunkStart[mid] <= chunk) lo = mid; else hi = mid;
  }
  uint t = lo;
  uint begin = tileStart[t] + (chunk - chunkStart[t]) * uChunk;
  uint end = min(min(begin + uChunk, tileStart[t + 1u]), uListCapacity);
  uint lid = gl_LocalInvocationIndex;
  for (uint px = lid; px < kTilePixels; px += kGroup)
    for (uint c = 0u; c < kSplatChannels; ++c) sSums[c][px] = 0u;
  barrier();
  // The tile's level, and where it lies on that level's grid.
  int level = 0;
  while (level + 1 < uSplatLevels && t >= splatTileOffset(size, level + 1)) ++level;
  uint local = t - splatTileOffset(size, level), across = uint(splatLevelTiles(size, level).x);
  ivec2 origin = ivec2(int(local % across), int(local / across)) * kSplatTile;
  // Where the splats are drawn: the tile itself, or its block of a coarser
  // level's pixels (drawSide a side), in the first rows and columns of sSums.
  int coarser = splatCoarsening(t, level);
  int drawLevel = level + coarser, drawSide = kSplatTile >> coarser;
  ivec2 drawOrigin = origin >> coarser;
  // The only chunk of a tile the scatter pass added nothing to may store its
  // sums, unless they go to a coarser level's pixels, or dense tiles of finer
  // levels may (render.splat_overlap on): both add with atomics.
  bool alone = chunkStart[t + 1u] - chunkStart[t] == 1u && tileStart[t + 1u] <= uListCapacity &&
               coarser == 0 && (look.splat.y <= 0.0 || level == 0);
  for (uint k = begin + lid; k < end; k += kGroup) {
    Splat s;
    if (!unpackSplat(tileList[k], drawLevel, s)) continue;
    ivec2 a = max(s.lo, drawOrigin), b = min(s.hi, drawOrigin + drawSide - 1);
    for (int y = a.y; y <= b.y; ++y) {
      ivec2 row = splatRow(s, y);
      for (int x = max(a.x, row.x); x <= min(b.x, row.y); ++x) {
        uint v[kSplatChannels];
        if (!splatAt(s, ivec2(x, y), v)) continue;
        uint px = uint((y - drawOrigin.y) * kSplatTile + (x - drawOrigin.x));
        for (uint c = 0u; c < kSplatChannels; ++c) atomicAdd(sSums[c][px], v[c]);
      }
    }
  }
  barrier();
  if (lid == 0u && end > begin) markSplatTiles(drawLevel, drawOrigin, drawOrigin);
  uvec2 levelSize = uvec2(splatLevelSize(size, drawLevel));
  uint offset = splatLevelOffset(size, drawLevel);
  for (uint px = lid; px < kTilePixels; px += kGroup) {
    uvec2 at = uvec2(px % uint(kSplatTile), px / uint(kSplatTile));
    if (at.x >= uint(drawSide) || at.y >= uint(drawSide)) continue;
    uvec2 p = uvec2(drawOrigin) + at;
    if (p.x >= levelSize.x || p.y >= levelSize.y) continue;
    uint base = (offset + p.y * levelSize.x + p.x) * kSplatStride;
    for (uint c = 0u; c < kSplatChannels; ++c) {
      uint v = sSums[c][px];
      if (v == 0u) continue;
      if (alone)
        accum[base + c] = v;
      else
        atomicAdd(accum[base + c], v);
    }
  }
#ifdef MOTION_FILTER
  // The chunk's splats' motion (splat_common.glsl), after the pixels so
  // their loop keeps its registers: integer sums over the workgroup in five
  // of the sums' shared words, then added to the tile's.
  barrier();
  if (lid < 5u) sSums[0][lid] = 0u;
  barrier();
  int shift = splatMotionShift(tileStart[t + 1u] - tileStart[t]);
  ivec4 motion = ivec4(0);
  int weight = 0;
  for (uint k = begin + lid; k < end; k += kGroup) {
    Splat s;
    if (!unpackSplat(tileList[k], level, s)) continue;
    ivec4 m;
    int w;
    splatMotionSums(s, shift, m, w);
    motion += m;
    weight += w;
  }
  if (weight != 0) {
    for (int c = 0; c < 4; ++c) atomicAdd(sSums[0][c], uint(motion[c]));
    atomicAdd(sSums[0][4], uint(weight));
  }
  barrier();
  if (lid < 5u && sSums[0][4] != 0u) {
    uint at = t * kSplatMotionStride + lid;
    if (alone)
      motionSums[at] = int(sSums[0][lid]);
    else
      atomicAdd(motionSums[at], int(sSums[0][lid]));
  }
#endif
}
