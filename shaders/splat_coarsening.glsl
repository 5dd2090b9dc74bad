// Whether the tiled pass draws a tile's splats one level coarser
// (render.splat_overlap, look.splat.y; 0: never): where splats cover each
// pixel of the tile and of the eight around it more than that many times on
// average, and the view has a coarser level. A pixel there holds the mean of
// so many splats that the sums vary slowly, and the coarser grid samples the
// same sums (the levels' halving is exact) at a quarter of the pixel
// evaluations: the look of render.splat_detail at half its value, inside
// dense clouds only. The neighbours keep a cloud's silhouette at the tile's
// own resolution: where the sums are opaque on one side and empty on the
// other, a coarser grid would draw the edge in steps of its pixels. (Two
// levels coarser, tried, also lost lines a few pixels wide inside the cloud.)
// A splat is taken as a disc 1.5 render.splat_detail wide, the middle of the
// detail to twice that its level draws it at. Needs splat_footprint.glsl and
// the tiles' list starts as `tileStart` (a tile's records: the next start
// less its own).
int splatCoarsening(uint tile, int level) {
  float limit = look.splat.y, width = 1.5 * max(look.splat.x, 1.0);
  if (limit <= 0.0 || level + 1 >= uSplatLevels) return 0;
  ivec2 size = ivec2(view.viewport.zw), tiles = splatLevelTiles(size, level);
  uint first = splatTileOffset(size, level);
  ivec2 at = ivec2(int(tile - first) % tiles.x, int(tile - first) / tiles.x);
  uint fewest = 0xffffffffu;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 n = at + ivec2(dx, dy);
      if (any(lessThan(n, ivec2(0))) || any(greaterThanEqual(n, tiles))) continue;
      uint t = first + uint(n.y * tiles.x + n.x);
      fewest = min(fewest, tileStart[t + 1u] - tileStart[t]);
    }
  float overlap = float(fewest) * 0.7853982 * width * width / float(kSplatTile * kSplatTile);
  return overlap > limit ? 1 : 0;
}
