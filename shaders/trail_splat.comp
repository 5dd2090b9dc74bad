#version 450 core
// ParticleSplat, trails, atomic variant (views too large for the tiled
// passes, and [gpu] splat = "atomic"): one invocation a trail segment walks
// its pixels (trail_common.glsl) and adds them to the splat sums with global
// atomics, two a pixel. Integer sums, so the order the segments arrive in
// does not matter, and the tiled passes add the same integers.
#include "view_block.glsl"
#include "render_block.glsl"
#include "splat_common.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 6) restrict buffer SplatAccumulation { uint accum[]; };
layout(std430, binding = 13) readonly restrict buffer Dispatch { uvec4 dispatch; };

#include "trail_common.glsl"

void trailAdd(ivec2 p, ivec2 origin, uint v[kSplatTrailChannels]) {
  uint base = (uint(p.y) * uint(view.viewport.z) + uint(p.x)) * kSplatStride + kSplatTrailChannel;
  atomicAdd(accum[base], v[0]);
  atomicAdd(accum[base + 1u], v[1]);
}

void main() {
  uint g = (gl_WorkGroupID.y * dispatch.x + gl_WorkGroupID.x) * 256u + gl_LocalInvocationIndex;
  uint segments = uint(uTrailLength - 1);
  uint o = g / segments;
  int j = int(g % segments);
  if (o >= dispatch.w) return;
  TrailSegment s;
  if (!trailSegment(o, j, s)) return;
  TrailLook l = trailLook(o);
  for (int step = 0; step < s.n; ++step) {
    ivec2 p = trailPixel(s, step);
    uint v[kSplatTrailChannels];
    if (trailOnScreen(p) && trailValues(s, l, step, p, v)) trailAdd(p, p, v);
  }
}
