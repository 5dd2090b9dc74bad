#version 450 core
// GpuRadixSort, pass 2: the digit-major table's exclusive prefix sum, in one
// workgroup: each thread sums a run of entries, the runs' sums are scanned in
// shared memory, and each thread writes its run's prefixes.
#include "radix_common.glsl"

layout(local_size_x = 1024) in;

shared uint sums[1024];

void main() {
  uint t = gl_LocalInvocationIndex;
  uint total = kDigits * uBlocks;
  uint run = (total + 1023u) / 1024u;
  uint first = t * run, last = min(first + run, total);
  uint sum = 0u;
  for (uint i = first; i < last; ++i) sum += radixTable[i];
  sums[t] = sum;
  barrier();
  for (uint step = 1u; step < 1024u; step <<= 1u) {  // inclusive Hillis-Steele
    uint add = t >= step ? sums[t - step] : 0u;
    barrier();
    sums[t] += add;
    barrier();
  }
  uint prefix = sums[t] - sum;
  for (uint i = first; i < last; ++i) {
    uint c = radixTable[i];
    radixTable[i] = prefix;
    prefix += c;
  }
}
