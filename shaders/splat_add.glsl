// Adds splat s's footprint over the pixels lo..hi (inclusive, in its level's
// pixels) to its level's sums with global atomics. Needs splat_footprint.glsl
// and the sums declared as `accum` (kSplatStride uints a pixel, each level's
// rows of its width, one level after another: splat_common.glsl), with
// MOTION_FILTER the motion blocks' sums as `motionSums`, and marks
// a coarser level's tiles it adds to (splat_occupied.glsl).
#include "splat_occupied.glsl"

// Adds the pixels lo..hi; returns what they added to channel 2.
uint addSplatPixels(Splat s, ivec2 lo, ivec2 hi) {
  ivec2 size = ivec2(view.viewport.zw);
  uint width = uint(splatLevelSize(size, s.level).x), offset = splatLevelOffset(size, s.level);
  uint drawn = 0u;
  for (int y = lo.y; y <= hi.y; ++y) {
    ivec2 row = splatRow(s, y);
    for (int x = max(lo.x, row.x); x <= min(hi.x, row.y); ++x) {
      uint v[kSplatChannels];
      if (!splatAt(s, ivec2(x, y), v)) continue;
      uint base = (offset + uint(y) * width + uint(x)) * kSplatStride;
      for (uint c = 0u; c < kSplatChannels; ++c) atomicAdd(accum[base + c], v[c]);
      drawn += v[2];
    }
  }
  return drawn;
}

void addSplat(Splat s, ivec2 lo, ivec2 hi) {
  markSplatTiles(s.level, lo, hi);
#ifdef MOTION_FILTER
  // Tile by tile, so its motion goes to the blocks the tiled pass gives it.
  ivec2 size = ivec2(view.viewport.zw), blocks = splatMotionBlocks(size, s.level);
  uint first = splatMotionBlockOffset(size, s.level);
  for (int ty = lo.y / kSplatTile; ty <= hi.y / kSplatTile; ++ty)
    for (int tx = lo.x / kSplatTile; tx <= hi.x / kSplatTile; ++tx) {
      ivec2 origin = ivec2(tx, ty) * kSplatTile;
      ivec2 a = max(lo, origin), b = min(hi, origin + kSplatTile - 1);
      uint drawn = addSplatPixels(s, a, b);
      if (drawn == 0u) continue;
      ivec4 m;
      int w;
      splatMotionSums(s, drawn, m, w);
      ivec2 from, to;
      splatMotionBlockRange(a, b, from, to);
      for (int by = from.y; by <= to.y; ++by)
        for (int bx = from.x; bx <= to.x; ++bx) {
          uint at = (first + uint(by * blocks.x + bx)) * 8u;
          for (int c = 0; c < 4; ++c) atomicAdd(motionSums[at + uint(c)], m[c]);
          atomicAdd(motionSums[at + 4u], w);
        }
    }
#else
  addSplatPixels(s, lo, hi);
#endif
}
