#version 450 core
// sandstorm-bench's shader copy ceiling: vec4 records from one storage buffer
// to another, one per invocation, as the particle update moves its records.
layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly restrict buffer From { vec4 from[]; };
layout(std430, binding = 1) writeonly restrict buffer To { vec4 to[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 256u + gl_LocalInvocationIndex;
  if (i < uCount) to[i] = from[i];
}
