#version 450 core
// ParticleSplat, tiled trails, step 5, as splat_tile.comp does for splats:
// one workgroup a chunk (at most uChunk runs of one tile's list; runs past
// the list's capacity were added by the scatter pass) adds its runs' pixels
// in the tile (trail_common.glsl) to sums in shared memory, then adds those
// to the view's sums, which hold the particles' splats already: a plain
// read and store where the chunk is its tile's only one, a global atomic
// where a dense tile has several.
#include "view_block.glsl"
#include "render_block.glsl"
#include "splat_common.glsl"

const uint kGroup = 512u;  // as splat_tile.comp's
layout(local_size_x = 512) in;
layout(std430, binding = 6) restrict buffer SplatAccumulation { uint accum[]; };
layout(std430, binding = 8) readonly restrict buffer TileLists { uvec2 runs[]; };
layout(std430, binding = 9) readonly restrict buffer TileStarts { uint tileStart[]; };
layout(std430, binding = 11) readonly restrict buffer ChunkStarts { uint chunkStart[]; };
layout(std430, binding = 12) readonly buffer ChunkDispatch {
  uvec4 dispatch;
  uint chunks;
} chunkArgs;
layout(location = 1) uniform uint uChunk;         // runs a chunk
layout(location = 2) uniform uint uListCapacity;  // runs

#include "trail_common.glsl"

const uint kTilePixels = uint(kSplatTile * kSplatTile);
shared uint sSums[kSplatTrailChannels][kTilePixels];

void trailAdd(ivec2 p, ivec2 origin, uint v[kSplatTrailChannels]) {
  uint px = uint((p.y - origin.y) * kSplatTile + (p.x - origin.x));
  atomicAdd(sSums[0][px], v[0]);
  atomicAdd(sSums[1][px], v[1]);
}

void main() {
  uint chunk = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  if (chunk >= chunkArgs.chunks) return;  // the whole workgroup
  ivec2 size = ivec2(view.viewport.zw);
  uint lo = 0u, hi = splatTileOffset(size, 1);
  while (hi - lo > 1u) {
    uint mid = (lo + hi) / 2u;
    if (chunkStart[mid] <= chunk) lo = mid; else hi = mid;
  }
  uint t = lo;
  uint begin = tileStart[t] + (chunk - chunkStart[t]) * uChunk;
  uint end = min(min(begin + uChunk, tileStart[t + 1u]), uListCapacity);
  bool alone = chunkStart[t + 1u] - chunkStart[t] == 1u && tileStart[t + 1u] <= uListCapacity;

  uint lid = gl_LocalInvocationIndex;
  for (uint px = lid; px < kTilePixels; px += kGroup)
    for (uint c = 0u; c < kSplatTrailChannels; ++c) sSums[c][px] = 0u;
  barrier();
  uint across = uint(splatLevelTiles(size, 0).x);
  ivec2 origin = ivec2(int(t % across), int(t / across)) * kSplatTile;
  for (uint k = begin + lid; k < end; k += kGroup) {
    uvec2 r = runs[k];
    trailRun(r.x, r.y & 0xffffu, r.y >> 16, origin);
  }
  barrier();
  for (uint px = lid; px < kTilePixels; px += kGroup) {
    uvec2 p = uvec2(origin) + uvec2(px % uint(kSplatTile), px / uint(kSplatTile));
    if (p.x >= uint(size.x) || p.y >= uint(size.y)) continue;
    uint base = (p.y * uint(size.x) + p.x) * kSplatStride + kSplatTrailChannel;
    for (uint c = 0u; c < kSplatTrailChannels; ++c) {
      uint v = sSums[c][px];
      if (v == 0u) continue;
      if (alone)
        accum[base + c] += v;
      else
        atomicAdd(accum[base + c], v);
    }
  }
}
