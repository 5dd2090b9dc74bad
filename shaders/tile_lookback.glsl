// The order-keeping compaction's look-back (Merrill & Garland 2016), shared by
// the particle and molecule updates: a tile that has scanned its own
// survivors publishes their count, adds up its predecessors' published counts
// (stopping at the first that published an inclusive prefix), then publishes
// its own inclusive prefix. A tile that waits too long for a predecessor
// counts that tile's survivors itself instead (the same rule, so the same
// count), so the result never depends on how workgroups are scheduled.
//
// With LOOKBACK_WAITS (contexts/particles/scan_spin.h: GPUs that run a
// dispatch's started workgroups side by side) a tile waits until its
// predecessor publishes, and the program has no recount: it holds the
// physics once, where the recount's copy cost the GPU's update registers.
//
// The includer declares, before this file: kItems and kTile (records a row
// and a tile: row k of tile t holds records t * kTile + k * 256 .. + 255),
// the status buffer `status[]` and the uniform uSpinLimit, and
// `bool survives(uint record)`: whether input record `record` lives through
// this update (called only without LOOKBACK_WAITS).

const uint kAggregate = 0x40000000u;  // status: this tile's own count is published
const uint kPrefix = 0x80000000u;     // status: the count of tiles 0..t is published
const uint kValue = 0x3fffffffu;

shared uint sStatus;
shared uint sCount;

// Publishes tile `tile`'s own survivor count `aggregate` and returns the
// survivors of tiles 0 .. tile-1 (the whole workgroup calls it, in step).
uint lookBack(uint tile, uint aggregate, uint inCount) {
  uint lid = gl_LocalInvocationIndex;
  if (lid == 0u) atomicExchange(status[tile], (tile == 0u ? kPrefix : kAggregate) | aggregate);
  // The loop is uniform: it follows shared values.
  uint prefix = 0u;
  for (int j = int(tile) - 1; j >= 0; --j) {
    if (lid == 0u) {
      uint s = 0u;
#ifdef LOOKBACK_WAITS
      // Tile j took its ticket first, so it is running and will publish.
      while ((s & (kAggregate | kPrefix)) == 0u) s = atomicOr(status[j], 0u);
#else
      for (uint spin = 0u; spin < uSpinLimit && (s & (kAggregate | kPrefix)) == 0u; ++spin)
        s = atomicOr(status[j], 0u);  // a coherent read; 0 while tile j has not published
#endif
      sStatus = s;
    }
    barrier();
    uint s = sStatus;
    barrier();  // everyone has read sStatus before it changes
    if ((s & (kAggregate | kPrefix)) != 0u) {
      prefix += s & kValue;
      if ((s & kPrefix) != 0u) break;
    }
#ifndef LOOKBACK_WAITS
    else {
      // Tile j is slow to publish: count its survivors here. Needed where
      // workgroups need not progress together (llvmpipe, which also ends any
      // shader's loops after 65535 iterations).
      if (lid == 0u) sCount = 0u;
      barrier();
      for (int k = 0; k < kItems; ++k) {
        uint i = uint(j) * kTile + uint(k) * 256u + lid;
        if (i < inCount && survives(i)) atomicAdd(sCount, 1u);
      }
      barrier();
      prefix += sCount;
      barrier();
    }
#endif
  }
  if (lid == 0u && tile > 0u) atomicExchange(status[tile], kPrefix | (prefix + aggregate));
  return prefix;
}
