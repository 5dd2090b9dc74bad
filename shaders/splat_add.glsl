// Adds splat s's footprint over the pixels lo..hi (inclusive, in its level's
// pixels) to its level's sums with global atomics. Needs splat_footprint.glsl
// and the sums declared as `accum` (kSplatStride uints a pixel, each level's
// rows of its width, one level after another: splat_common.glsl), with
// MOTION_FILTER the tiles' motion sums as `motionSums`, and marks
// a coarser level's tiles it adds to (splat_occupied.glsl).
#include "splat_occupied.glsl"

// Its footprint alone.
void addSplatPixels(Splat s, ivec2 lo, ivec2 hi) {
  markSplatTiles(s.level, lo, hi);
  ivec2 size = ivec2(view.viewport.zw);
  uint width = uint(splatLevelSize(size, s.level).x), offset = splatLevelOffset(size, s.level);
  for (int y = lo.y; y <= hi.y; ++y) {
    ivec2 row = splatRow(s, y);
    for (int x = max(lo.x, row.x); x <= min(hi.x, row.y); ++x) {
      uint v[kSplatChannels];
      if (!splatAt(s, ivec2(x, y), v)) continue;
      uint base = (offset + uint(y) * width + uint(x)) * kSplatStride;
      for (uint c = 0u; c < kSplatChannels; ++c) atomicAdd(accum[base + c], v[c]);
    }
  }
}

// Its motion alone, to each tile of its level it covers, as the tiled pass adds it.
void addSplatMotion(Splat s, ivec2 lo, ivec2 hi, int motionShift) {
#ifdef MOTION_FILTER
  ivec2 size = ivec2(view.viewport.zw);
  ivec4 m;
  int w;
  splatMotionSums(s, motionShift, m, w);
  if (w == 0) return;
  uint first = splatTileOffset(size, s.level), across = uint(splatLevelTiles(size, s.level).x);
  for (int ty = lo.y / kSplatTile; ty <= hi.y / kSplatTile; ++ty)
    for (int tx = lo.x / kSplatTile; tx <= hi.x / kSplatTile; ++tx) {
      uint at = (first + uint(ty) * across + uint(tx)) * kSplatMotionStride;
      for (int c = 0; c < 4; ++c) atomicAdd(motionSums[at + uint(c)], m[c]);
      atomicAdd(motionSums[at + 4u], w);
    }
#endif
}

void addSplat(Splat s, ivec2 lo, ivec2 hi, int motionShift) {
  addSplatPixels(s, lo, hi);
  addSplatMotion(s, lo, hi, motionShift);
}
