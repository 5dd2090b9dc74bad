// GpuRadixSort's shared declarations (contexts/sort/gpu_radix_sort.h).
const uint kRadixBlock = 1024u;  // keys a workgroup handles: 256 threads x 4
const uint kRadixItems = 4u;
const uint kDigits = 16u;  // 4-bit digits

layout(std430, binding = 0) readonly restrict buffer RadixCount { uint radixCount; };
layout(std430, binding = 3) restrict buffer RadixTable { uint radixTable[]; };  // digit-major

layout(location = 0) uniform uint uShift;      // the digit's lowest bit
layout(location = 1) uniform uint uBlocks;     // blocks of the capacity (the table's width)
layout(location = 2) uniform uint uRowGroups;  // workgroups a row of the 2D dispatch

uint radixBlockIndex() { return gl_WorkGroupID.y * uRowGroups + gl_WorkGroupID.x; }
