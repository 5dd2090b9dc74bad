// Adds one to a shared-memory counter for each invocation that calls it, and
// returns what the add returned for it (its slot): the counters of a
// histogram in shared memory, `sBins`, declared before the include.
// Where many invocations of a subgroup add to the same counter (a view whose
// particles crowd into a few tiles), each of their atomics waits for the one
// before: so the invocations that add to the same counter as the subgroup's
// first active one add together, one atomic for all of them (its count), and
// take consecutive slots from what it returned; the others add alone. The
// slots are as distinct and as many as one atomic each would give, in another
// order, which every caller allows for (its order already varied with the
// scheduling). Needs GL_ARB_shader_ballot (and 64-bit integers for its
// ballots); without it every invocation adds alone.
// The file that includes this must enable both extensions before any other
// line: `#extension GL_ARB_shader_ballot : enable` and
// `#extension GL_ARB_gpu_shader_int64 : enable`.

#if defined(GL_ARB_shader_ballot) && defined(GL_ARB_gpu_shader_int64)
uint bitCount64(uint64_t bits) {
  uvec2 words = unpackUint2x32(bits);
  return uint(bitCount(words.x) + bitCount(words.y));
}
#endif

uint addToBin(uint bin) {
#if defined(GL_ARB_shader_ballot) && defined(GL_ARB_gpu_shader_int64)
  uint first = readFirstInvocationARB(bin);
  uint64_t same = ballotARB(bin == first);
  uint rank = bitCount64(same & gl_SubGroupLtMaskARB);
  uint base = 0u;
  // The first active invocation adds for all of them: the first of `same`.
  if (bin == first && rank == 0u) base = atomicAdd(sBins[bin], bitCount64(same));
  base = readFirstInvocationARB(base);
  if (bin == first) return base + rank;
#endif
  return atomicAdd(sBins[bin], 1u);
}
