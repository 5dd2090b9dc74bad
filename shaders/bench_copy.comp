#version 450 core
// sandstorm-bench's shader copy ceiling: vec4 records from one storage buffer
// to another, four per invocation (all loads issued before the stores), as
// the particle update moves its records.
layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly restrict buffer From { vec4 from[]; };
layout(std430, binding = 1) writeonly restrict buffer To { vec4 to[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint base = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 1024u + gl_LocalInvocationIndex;
  vec4 v[4];
  for (uint k = 0u; k < 4u; ++k) {
    uint i = base + k * 256u;
    if (i < uCount) v[k] = from[i];
  }
  for (uint k = 0u; k < 4u; ++k) {
    uint i = base + k * 256u;
    if (i < uCount) to[i] = v[k];
  }
}
