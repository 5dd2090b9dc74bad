// Adds splat s's footprint over the pixels lo..hi (inclusive) to the view's
// sums with global atomics. Needs splat_footprint.glsl and the sums declared
// as `accum` (kSplatStride uints a pixel, rows of the view's width).
void addSplat(Splat s, ivec2 lo, ivec2 hi) {
  uint width = uint(view.viewport.z);
  for (int y = lo.y; y <= hi.y; ++y) {
    ivec2 row = splatRow(s, y);
    for (int x = max(lo.x, row.x); x <= min(hi.x, row.y); ++x) {
      uint v[kSplatChannels];
      if (!splatAt(s, ivec2(x, y), v)) continue;
      uint base = (uint(y) * width + uint(x)) * kSplatStride;
      for (uint c = 0u; c < kSplatChannels; ++c) atomicAdd(accum[base + c], v[c]);
    }
  }
}
