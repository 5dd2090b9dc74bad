// The order-keeping compaction's look-back (Merrill & Garland 2016), shared by
// the particle and molecule updates: a tile that has scanned its own
// survivors publishes their count, adds up its predecessors' published counts
// (stopping at the first that published an inclusive prefix), then publishes
// its own inclusive prefix. A tile that waits too long for a predecessor
// counts that tile's survivors itself instead (the same rule, so the same
// count), so the result never depends on how workgroups are scheduled.
//
// The includer steps records at one place only: its main loop steps the
// records of tile `target`, first its own tile, then each predecessor that
// lookBackTo() hands back for counting. (A second copy of the physics, for
// the recount, made llvmpipe's compile of these shaders 3-4x slower: it turns
// a shader with barriers into coroutines, at a cost that grows with the code.)
//
//   int j = int(tile) - 1;  // the next predecessor to look at
//   uint prefix = 0u;       // survivors of tiles j+1 .. tile-1
//   for (int target = int(tile); target >= 0;) {
//     ... step tile target's records ...
//     if (target == int(tile)) { ... scan them ...; publishAggregate(tile, aggregate); }
//     else { prefix += workgroupSum(survivorsOfMine); --j; }
//     target = lookBackTo(tile, aggregate, j, prefix);
//   }
//
// The includer declares, before this file, the status buffer `status[]` and
// the uniform uSpinLimit.

const uint kAggregate = 0x40000000u;  // status: this tile's own count is published
const uint kPrefix = 0x80000000u;     // status: the count of tiles 0..t is published
const uint kValue = 0x3fffffffu;

shared uint sStatus;
shared uint sCount;

// Publishes tile `tile`'s own survivor count (the whole workgroup calls it).
void publishAggregate(uint tile, uint aggregate) {
  if (gl_LocalInvocationIndex == 0u)
    atomicExchange(status[tile], (tile == 0u ? kPrefix : kAggregate) | aggregate);
}

// Adds the published counts of tiles j, j-1, ... to `prefix`. Returns the
// first of them that has not published within uSpinLimit reads (j is left at
// it: the caller counts its survivors, adds them and steps j past it), or -1
// once `prefix` holds the survivors of tiles 0 .. tile-1; then tile `tile`'s
// inclusive prefix is published. The whole workgroup calls it, in step: the
// loop follows shared values.
int lookBackTo(uint tile, uint aggregate, inout int j, inout uint prefix) {
  uint lid = gl_LocalInvocationIndex;
  bool complete = false;
  while (j >= 0 && !complete) {
    if (lid == 0u) {
      uint s = 0u;
      for (uint spin = 0u; spin < uSpinLimit && (s & (kAggregate | kPrefix)) == 0u; ++spin)
        s = atomicOr(status[j], 0u);  // a coherent read; 0 while tile j has not published
      sStatus = s;
    }
    barrier();
    uint s = sStatus;
    barrier();  // everyone has read sStatus before it changes
    // Tile j is slow to publish: it is counted here. Needed where workgroups
    // need not progress together (llvmpipe, which also ends any shader's
    // loops after 65535 iterations).
    if ((s & (kAggregate | kPrefix)) == 0u) return j;
    prefix += s & kValue;
    complete = (s & kPrefix) != 0u;
    --j;
  }
  if (lid == 0u && tile > 0u) atomicExchange(status[tile], kPrefix | (prefix + aggregate));
  return -1;
}

// The sum over the workgroup of each invocation's `mine`.
uint workgroupSum(uint mine) {
  if (gl_LocalInvocationIndex == 0u) sCount = 0u;
  barrier();
  if (mine != 0u) atomicAdd(sCount, mine);
  barrier();
  uint sum = sCount;
  barrier();  // everyone has read sCount before it changes
  return sum;
}
