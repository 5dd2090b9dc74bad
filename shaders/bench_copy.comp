#version 450 core
// sandstorm-bench's shader copy ceiling: vec4 records from one storage buffer
// to another, ITEMS per invocation (all loads issued before the stores), as
// the particle update moves its records. The benchmark keeps the fastest of
// several ITEMS.
#ifndef ITEMS
#define ITEMS 4
#endif
layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly restrict buffer From { vec4 from[]; };
layout(std430, binding = 1) writeonly restrict buffer To { vec4 to[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint base = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * (256u * ITEMS) + gl_LocalInvocationIndex;
  vec4 v[ITEMS];
  for (uint k = 0u; k < ITEMS; ++k) {
    uint i = base + k * 256u;
    if (i < uCount) v[k] = from[i];
  }
  for (uint k = 0u; k < ITEMS; ++k) {
    uint i = base + k * 256u;
    if (i < uCount) to[i] = v[k];
  }
}
