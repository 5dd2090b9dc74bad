#version 450 core
// ParticleMotionFilter, step 2: for each 16-pixel tile, the longest motion
// axis among the cells around it (particle_motion_field.comp) whose motion
// can reach it (a smear is at most 48 pixels: splat_footprint.glsl's
// kMaxSmear). The filter gathers as far as that reaches, along it where the
// pixel itself is still. One invocation a tile.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 3) uniform sampler2D uCells;  // the motion's and its axis's means, 8-pixel cells
layout(rg16f, binding = 5) writeonly uniform image2D uReach;
layout(location = 0) uniform ivec2 uSize;

const int kCell = 8, kTile = 16, kMaxSmear = 48;

void main() {
  ivec2 tile = ivec2(gl_GlobalInvocationID.xy);
  if (tile.x * kTile >= uSize.x || tile.y * kTile >= uSize.y) return;
  ivec2 cells = textureSize(uCells, 0);
  ivec2 lo = tile * kTile, hi = lo + kTile - 1;  // the tile's pixels
  ivec2 c0 = max((lo - kMaxSmear) / kCell, ivec2(0)), c1 = min((hi + kMaxSmear) / kCell, cells - 1);
  vec2 longest = vec2(0.0);
  for (int y = c0.y; y <= c1.y; ++y)
    for (int x = c0.x; x <= c1.x; ++x) {
      vec2 m = texelFetch(uCells, ivec2(x, y), 0).zw;
      ivec2 a = ivec2(x, y) * kCell, b = a + kCell - 1;
      ivec2 gap = max(max(a - hi, lo - b), ivec2(0));  // pixels between the cell and the tile
      if (dot(m, m) > dot(longest, longest) && length(m) >= float(max(gap.x, gap.y))) longest = m;
    }
  imageStore(uReach, tile, vec4(longest, 0.0, 0.0));
}
