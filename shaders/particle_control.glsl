// The compute updates' control block (particles' and molecules'): the twin of
// the offsets in contexts/particles/update_control.h.
layout(std430, binding = 4) coherent restrict buffer Control {
  uint count[2];  // live records of each buffer set
  uint ticket;    // the update pass's next tile
  uint tiles;     // tiles of this update
  uvec4 dispatch; // glDispatchComputeIndirect: x, y, z, (unused)
  uvec4 draw[2];  // glDrawArraysIndirect per set: count, instances, first, base instance
} ctl;

#ifndef ITEMS
#define ITEMS 4
#endif
const int kItems = ITEMS;                 // records per invocation of the update: 1, 2, 4 or 8
const uint kTile = 256u * uint(ITEMS);    // input records per tile: 256 invocations x kItems
const uint kGroupsPerRow = 32768u;  // the update's dispatch is 2D beyond this many tiles
