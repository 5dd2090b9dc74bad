#version 450 core
// TrailRenderer: the draw command for the live records' trail segments, made
// on the GPU from the live count (nothing is read back).
layout(local_size_x = 1) in;
layout(std430, binding = 4) readonly restrict buffer Count { uint counts[]; };
layout(std430, binding = 9) writeonly restrict buffer Command { uvec4 command; };
layout(location = 0) uniform uint uCountIndex;
layout(location = 1) uniform uint uCountAdd;
layout(location = 2) uniform uint uVerticesPerRecord;
layout(location = 3) uniform uint uCapacity;

void main() {
  uint live = min(counts[uCountIndex] + uCountAdd, uCapacity);
  command = uvec4(live * uVerticesPerRecord, 1u, 0u, 0u);
}
