#version 450 core
// ParticleSplat, atomic variant, step 2: each invocation splats one particle
// into the pixels its billboard would cover, adding to the view's sums in a
// buffer with global atomics (splat_common.glsl, splat_footprint.glsl).
#include "view_block.glsl"
#include "render_block.glsl"
#include "splat_common.glsl"
#include "splat_footprint.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 1) readonly restrict buffer VelocityKind { vec4 velocityKind[]; };
layout(std430, binding = 5) readonly buffer Dispatch {
  uvec4 dispatch;
  uint count;
} args;
layout(std430, binding = 6) restrict buffer SplatAccumulation { uint accum[]; };
#ifdef MOTION_FILTER
layout(std430, binding = 16) restrict buffer SplatMotion { int motionSums[]; };
#endif

#include "splat_add.glsl"

void main() {
  uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 256u + gl_LocalInvocationIndex;
  if (i >= args.count) return;
  Splat s;
  if (makeSplat(positionLife[i], velocityKind[i], s)) addSplat(s, s.lo, s.hi, 0);
}
