#version 450 core
// GpuRadixSort, pass 1: block b's count of each digit, at radixTable[d * uBlocks + b].
// Thread t holds keys b * 1024 + t * 4 .. + 3 (the scatter's layout).
#include "radix_common.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 1) readonly restrict buffer Keys { uint keys[]; };

shared uint counts[kDigits];

void main() {
  uint b = radixBlockIndex();
  uint t = gl_LocalInvocationIndex;
  if (t < kDigits) counts[t] = 0u;
  barrier();
  if (b < uBlocks) {
    uint n = radixCount;
    for (uint i = 0u; i < kRadixItems; ++i) {
      uint k = b * kRadixBlock + t * kRadixItems + i;
      if (k < n) atomicAdd(counts[(keys[k] >> uShift) & (kDigits - 1u)], 1u);
    }
  }
  barrier();
  if (b < uBlocks && t < kDigits) radixTable[t * uBlocks + b] = counts[t];
}
