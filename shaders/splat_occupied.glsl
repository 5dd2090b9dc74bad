// Which tiles of the coarser levels (render.splat_detail) have splats: the
// passes that add a level's sums mark the 32x32-pixel tiles they add to, and
// the resolve reads a level only around marked tiles, so views whose splats
// all sit at full resolution, or whose coarse splats cover little, pay
// nothing for the levels' taps. Needs splat_common.glsl; ParticleSplat clears
// the marks after each view. Indexed like the tiled pass's tiles
// (splatTileOffset: level 0's first, unused).
layout(std430, binding = 14) restrict buffer SplatOccupied { uint occupied[]; };

// Marks the tiles of `level` under its pixels lo..hi (inclusive).
void markSplatTiles(int level, ivec2 lo, ivec2 hi) {
  if (level == 0) return;
  ivec2 size = ivec2(view.viewport.zw);
  uint first = splatTileOffset(size, level), across = uint(splatLevelTiles(size, level).x);
  ivec2 t0 = lo / kSplatTile, t1 = hi / kSplatTile;
  for (int ty = t0.y; ty <= t1.y; ++ty)
    for (int tx = t0.x; tx <= t1.x; ++tx) occupied[first + uint(ty) * across + uint(tx)] = 1u;
}
