#version 450 core
// Trails: a pass's dispatch from the live count, one invocation an item of
// each live record (a trail's segment for ParticleSplat's atomic trails, a
// ring slot for ParticleTrails' update), a 2D grid of at most 32768
// workgroups of 256 a row; w: the live records.
layout(local_size_x = 1) in;
layout(std430, binding = 4) readonly restrict buffer Count { uint counts[]; };
layout(std430, binding = 13) writeonly restrict buffer Dispatch { uvec4 dispatch; };
layout(location = 0) uniform uint uCountIndex;
layout(location = 1) uniform uint uCountAdd;
layout(location = 2) uniform uint uItems;  // a record's
layout(location = 3) uniform uint uCapacity;

void main() {
  uint live = min(counts[uCountIndex] + uCountAdd, uCapacity);
  uint groups = (live * uItems + 255u) / 256u;
  uint row = max(min(groups, 32768u), 1u);
  dispatch = uvec4(groups == 0u ? 0u : row, (groups + row - 1u) / row, 1u, live);
}
