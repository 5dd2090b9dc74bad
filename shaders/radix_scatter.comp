#version 450 core
// GpuRadixSort, pass 3: every key of block b goes to the table's start of its
// digit for the block plus its rank among the block's keys of that digit in
// input order (threads in order, each thread's four keys in order), so the
// pass is stable.
#include "radix_common.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 1) readonly restrict buffer KeysIn { uint keysIn[]; };
layout(std430, binding = 2) readonly restrict buffer ValuesIn { uint valuesIn[]; };
layout(std430, binding = 4) writeonly restrict buffer KeysOut { uint keysOut[]; };
layout(std430, binding = 5) writeonly restrict buffer ValuesOut { uint valuesOut[]; };

shared uint ranks[kDigits * 256u];  // (digit, thread): its keys of that digit, then their prefix
shared uint partial[256];

void main() {
  uint b = radixBlockIndex();
  if (b >= uBlocks) return;  // the whole workgroup leaves together
  uint t = gl_LocalInvocationIndex;
  uint n = radixCount;
  uint key[kRadixItems], value[kRadixItems], digit[kRadixItems];
  for (uint d = 0u; d < kDigits; ++d) ranks[d * 256u + t] = 0u;
  for (uint i = 0u; i < kRadixItems; ++i) {
    uint k = b * kRadixBlock + t * kRadixItems + i;
    digit[i] = kDigits;  // none
    if (k < n) {
      key[i] = keysIn[k];
      value[i] = valuesIn[k];
      digit[i] = (key[i] >> uShift) & (kDigits - 1u);
      ranks[digit[i] * 256u + t] += 1u;
    }
  }
  barrier();
  // Exclusive scan of ranks (4096 entries), 16 contiguous entries a thread.
  uint sum = 0u;
  for (uint j = 0u; j < 16u; ++j) sum += ranks[t * 16u + j];
  partial[t] = sum;
  barrier();
  for (uint step = 1u; step < 256u; step <<= 1u) {
    uint add = t >= step ? partial[t - step] : 0u;
    barrier();
    partial[t] += add;
    barrier();
  }
  uint prefix = partial[t] - sum;
  for (uint j = 0u; j < 16u; ++j) {
    uint c = ranks[t * 16u + j];
    ranks[t * 16u + j] = prefix;
    prefix += c;
  }
  barrier();
  uint seen[kDigits];
  for (uint d = 0u; d < kDigits; ++d) seen[d] = 0u;
  for (uint i = 0u; i < kRadixItems; ++i) {
    uint d = digit[i];
    if (d >= kDigits) continue;
    uint rank = ranks[d * 256u + t] - ranks[d * 256u] + seen[d];
    seen[d] += 1u;
    uint at = radixTable[d * uBlocks + b] + rank;
    keysOut[at] = key[i];
    valuesOut[at] = value[i];
  }
}
