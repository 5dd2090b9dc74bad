#version 450 core
// ParticleMotionFilter, step 2: for each 16-pixel tile, the longest motion
// axis among the tiles around it whose motion can reach it (a tile k tiles
// away is at least (k - 1) 16 pixels off; a smear is at most 48 pixels:
// splat_footprint.glsl's kMaxSmear, so 3 tiles a side). The filter gathers
// as far as that reaches, along it where the pixel itself is still.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 4) uniform sampler2D uTiles;  // the longest axis a tile
layout(rg16f, binding = 5) writeonly uniform image2D uReach;

const int kMotionTile = 16, kAround = 3;

void main() {
  ivec2 tile = ivec2(gl_GlobalInvocationID.xy), tiles = textureSize(uTiles, 0);
  if (tile.x >= tiles.x || tile.y >= tiles.y) return;
  vec2 longest = vec2(0.0);
  for (int y = -kAround; y <= kAround; ++y)
    for (int x = -kAround; x <= kAround; ++x) {
      ivec2 t = tile + ivec2(x, y);
      if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, tiles))) continue;
      vec2 m = texelFetch(uTiles, t, 0).xy;
      float gap = float(max(max(abs(x), abs(y)) - 1, 0) * kMotionTile);
      if (dot(m, m) > dot(longest, longest) && length(m) >= gap) longest = m;
    }
  imageStore(uReach, tile, vec4(longest, 0.0, 0.0));
}
