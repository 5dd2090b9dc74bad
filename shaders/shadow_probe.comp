#version 450 core
// OpacityShadowMap::transmittance: lightTransmittance at given points, as
// every receiver computes it (tests).
#include "shadow_block.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly restrict buffer Points { vec4 points[]; };
layout(std430, binding = 1) writeonly restrict buffer Result { float result[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < uCount) result[i] = lightTransmittance(points[i].xyz);
}
