#version 450 core
// ParticleMotionFilter, step 1: the splats' motion field at the centre of
// every 8x8-pixel cell of the view: each level's tile sums (splat_common.
// glsl) interpolated bilinearly between the tiles' centres and added, then
// the means: the motion and its doubled-angle axis, view pixels over the
// shutter (zero where no splat is near). One invocation a cell.
#include "view_block.glsl"
#include "splat_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, binding = 16) readonly restrict buffer SplatMotion { ivec4 motionSums[]; };  // two a tile
layout(rgba16f, binding = 3) writeonly uniform image2D uCells;
layout(location = 0) uniform ivec2 uSize;
layout(location = 15) uniform int uSplatLevels;

const int kCell = 8;

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (cell.x * kCell >= uSize.x || cell.y * kCell >= uSize.y) return;
  vec2 centre = vec2(cell * kCell) + 0.5 * float(kCell);
  vec4 sum = vec4(0.0);
  float weight = 0.0;
  for (int level = 0; level < uSplatLevels; ++level) {
    ivec2 tiles = splatLevelTiles(uSize, level);
    vec2 at = centre / float(kSplatTile << level) - 0.5;
    ivec2 i0 = ivec2(floor(at));
    vec2 f = at - vec2(i0);
    uint first = splatTileOffset(uSize, level);
    for (int dy = 0; dy <= 1; ++dy)
      for (int dx = 0; dx <= 1; ++dx) {
        float w = (dx == 0 ? 1.0 - f.x : f.x) * (dy == 0 ? 1.0 - f.y : f.y);
        ivec2 q = clamp(i0 + ivec2(dx, dy), ivec2(0), tiles - 1);
        uint t = first + uint(q.y) * uint(tiles.x) + uint(q.x);
        sum += w * vec4(motionSums[t * 2u]);
        weight += w * float(motionSums[t * 2u + 1u].x);
      }
  }
  // The sums are in half pixels.
  imageStore(uCells, cell, weight > 0.0 ? 0.5 * sum / weight : vec4(0.0));
}
