#version 450 core
// ParticleSort: each live record's sort key, its distance from the eye along
// the view (farther first: the complement of the distance's ordered bits),
// its index as the value, and the draw command for the live count.
#include "view_block.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 4) readonly restrict buffer Count { uint counts[]; };
layout(std430, binding = 5) writeonly restrict buffer Keys { uint keys[]; };
layout(std430, binding = 6) writeonly restrict buffer Values { uint values[]; };
layout(std430, binding = 7) writeonly restrict buffer Command { uvec4 command; };  // DrawArraysIndirect
layout(location = 0) uniform uint uCountIndex;
layout(location = 1) uniform uint uCountAdd;
layout(location = 2) uniform uint uRowGroups;

#include "ordered_bits.glsl"

void main() {
  uint i = (gl_WorkGroupID.y * uRowGroups + gl_WorkGroupID.x) * 256u + gl_LocalInvocationIndex;
  uint count = counts[uCountIndex] + uCountAdd;
  if (i == 0u) command = uvec4(count, 1u, 0u, 0u);
  if (i >= count) return;
  float distance = -(view.viewMatrix * vec4(positionLife[i].xyz, 1.0)).z;
  keys[i] = ~ordered(distance);
  values[i] = i;
}
