#version 450 core
// ParticleSplat, after the resolve where the view used coarser levels
// (render.splat_detail): one workgroup a tile of those levels zeroes the sums
// of a marked tile and its mark (splat_occupied.glsl) for the next view; an
// unmarked tile has nothing to zero. (A buffer clear of the levels' sums, 22 MB
// for a 1920x1080 view, took 0.7 ms a view on an H100.)
#include "view_block.glsl"
#include "splat_common.glsl"
#include "splat_occupied.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 6) writeonly restrict buffer SplatAccumulation { uvec4 accum[]; };
layout(location = 15) uniform int uSplatLevels;  // as splat_footprint.glsl's

shared bool sMarked;

void main() {
  ivec2 size = ivec2(view.viewport.zw);
  uint t = splatTileOffset(size, 1) + gl_WorkGroupID.x;
  if (gl_LocalInvocationIndex == 0u) sMarked = occupied[t] != 0u;
  barrier();
  if (!sMarked) return;
  int level = 1;
  while (level + 1 < uSplatLevels && t >= splatTileOffset(size, level + 1)) ++level;
  uint local = t - splatTileOffset(size, level), across = uint(splatLevelTiles(size, level).x);
  ivec2 origin = ivec2(int(local % across), int(local / across)) * kSplatTile;
  ivec2 levelSize = splatLevelSize(size, level);
  uint offset = splatLevelOffset(size, level);
  for (uint px = gl_LocalInvocationIndex; px < uint(kSplatTile * kSplatTile); px += 256u) {
    ivec2 p = origin + ivec2(int(px) % kSplatTile, int(px) / kSplatTile);
    if (p.x >= levelSize.x || p.y >= levelSize.y) continue;
    uint index = offset + uint(p.y) * uint(levelSize.x) + uint(p.x);
    accum[index * 2u] = uvec4(0u);
    accum[index * 2u + 1u] = uvec4(0u);
  }
  if (gl_LocalInvocationIndex == 0u) occupied[t] = 0u;
}
