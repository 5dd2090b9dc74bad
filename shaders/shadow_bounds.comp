#version 450 core
// OpacityShadowMap, step 1: the live particles' extent in the light's frame
// (least and greatest along right, up and toLight), by atomics on
// order-preserving integers (exact, so the same whatever the order).
#include "ordered_bits.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 4) readonly restrict buffer Counts { uint counts[]; };
layout(std430, binding = 14) restrict buffer Bounds { uint least[3]; uint greatest[3]; } bounds;
layout(location = 0) uniform uint uCountIndex;
layout(location = 1) uniform uint uCountAdd;
layout(location = 2) uniform vec3 uRight;
layout(location = 3) uniform vec3 uUp;
layout(location = 4) uniform vec3 uToLight;

shared uint sLeast[3], sGreatest[3];

void main() {
  if (gl_LocalInvocationIndex < 3u) {
    sLeast[gl_LocalInvocationIndex] = 0xffffffffu;
    sGreatest[gl_LocalInvocationIndex] = 0u;
  }
  barrier();
  uint count = counts[uCountIndex] + uCountAdd;
  uint stride = gl_NumWorkGroups.x * 256u;
  uvec3 lo = uvec3(0xffffffffu), hi = uvec3(0u);
  for (uint i = gl_GlobalInvocationID.x; i < count; i += stride) {
    vec3 p = positionLife[i].xyz;
    uvec3 q = uvec3(ordered(dot(p, uRight)), ordered(dot(p, uUp)), ordered(dot(p, uToLight)));
    lo = min(lo, q);
    hi = max(hi, q);
  }
  for (int a = 0; a < 3; ++a) {
    atomicMin(sLeast[a], lo[a]);
    atomicMax(sGreatest[a], hi[a]);
  }
  barrier();
  if (gl_LocalInvocationIndex < 3u) {
    atomicMin(bounds.least[gl_LocalInvocationIndex], sLeast[gl_LocalInvocationIndex]);
    atomicMax(bounds.greatest[gl_LocalInvocationIndex], sGreatest[gl_LocalInvocationIndex]);
  }
}
