#version 450 core
// ParticleSplat, tiled variant, step 5: one workgroup a tile. The tile's
// particles (its list) add to its pixels' sums in shared memory, then each
// invocation resolves its own pixel into the particle buffers (resolveSplat):
// the same sums as the atomic variant, so the same image, without a global
// atomic per pixel and channel.
#include "view_block.glsl"
#include "render_block.glsl"
#include "splat_common.glsl"
#include "splat_footprint.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(std430, binding = 0) readonly restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 1) readonly restrict buffer VelocityKind { vec4 velocityKind[]; };
layout(std430, binding = 8) readonly restrict buffer TileLists { uint tileList[]; };
layout(std430, binding = 9) readonly restrict buffer TileStarts { uint tileStart[]; };
layout(rgba16f, binding = 0) writeonly uniform image2D uColor;
layout(rgba16f, binding = 1) writeonly uniform image2D uNormal;
layout(location = 0) uniform ivec2 uTiles;
layout(location = 1) uniform uint uListCapacity;

shared uint sSums[kSplatChannels][kSplatTile * kSplatTile];

void main() {
  uint lid = gl_LocalInvocationIndex;
  for (uint c = 0u; c < kSplatChannels; ++c) sSums[c][lid] = 0u;
  barrier();
  ivec2 tile = ivec2(gl_WorkGroupID.xy);
  ivec2 origin = tile * kSplatTile;
  uint t = uint(tile.y * uTiles.x + tile.x);
  uint begin = min(tileStart[t], uListCapacity), end = min(tileStart[t + 1u], uListCapacity);
  for (uint k = begin + lid; k < end; k += 256u) {
    uint i = tileList[k];
    Splat s;
    if (!makeSplat(positionLife[i], velocityKind[i], s)) continue;
    ivec2 lo = max(s.lo, origin), hi = min(s.hi, origin + kSplatTile - 1);
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) {
        uint v[kSplatChannels];
        if (!splatAt(s, ivec2(x, y), v)) continue;
        uint px = uint((y - origin.y) * kSplatTile + (x - origin.x));
        for (uint c = 0u; c < kSplatChannels; ++c) atomicAdd(sSums[c][px], v[c]);
      }
  }
  barrier();
  ivec2 p = origin + ivec2(gl_LocalInvocationID.xy);
  if (p.x >= int(view.viewport.z) || p.y >= int(view.viewport.w)) return;
  uint sums[kSplatChannels];
  for (uint c = 0u; c < kSplatChannels; ++c) sums[c] = sSums[c][lid];
  vec4 color, normal;
  resolveSplat(sums, color, normal);
  imageStore(uColor, p, color);
  imageStore(uNormal, p, normal);
}
