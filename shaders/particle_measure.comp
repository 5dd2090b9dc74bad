#version 450 core
// ParticleMeasure: over the live records, the particles within the probe's
// radius and the least and greatest value of the colour quantity (the render
// block's), by atomics on order-preserving integer images of the floats.
#include "render_block.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 1) readonly restrict buffer VelocityKind { vec4 velocityKind[]; };
layout(std430, binding = 4) readonly restrict buffer Count { uint counts[]; };
layout(std430, binding = 10) restrict buffer Result { uint near; uint least; uint greatest; uint live; };
layout(location = 0) uniform uint uCountIndex;
layout(location = 1) uniform uint uCountAdd;
layout(location = 2) uniform vec4 uProbe;  // xyz, w: radius^2 (< 0: no probe)
layout(location = 3) uniform uint uRowGroups;

#include "ordered_bits.glsl"

void main() {
  uint i = (gl_WorkGroupID.y * uRowGroups + gl_WorkGroupID.x) * 256u + gl_LocalInvocationIndex;
  uint count = counts[uCountIndex] + uCountAdd;
  if (i == 0u) live = count;
  if (i >= count) return;
  vec4 pl = positionLife[i], vk = velocityKind[i];
  if (uProbe.w >= 0.0) {
    vec3 d = pl.xyz - uProbe.xyz;
    if (dot(d, d) <= uProbe.w) atomicAdd(near, 1u);
  }
  float age = clamp(1.0 - pl.w / max(vk.w, 1e-6), 0.0, 1.0);
  float v = colorValue(age, vk.xyz, pl.xyz);
  if (isnan(v) || isinf(v)) return;
  uint o = ordered(v);
  atomicMin(least, o);
  atomicMax(greatest, o);
}
