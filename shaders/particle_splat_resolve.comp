#version 450 core
// ParticleSplat, atomic variant, step 3: turns each pixel's sums into what
// ParticleRender's blending leaves in the particle buffers (resolveSplat) and
// zeroes the sums for the next view.
#include "render_block.glsl"
#include "splat_common.glsl"
#include "view_block.glsl"
#include "splat_footprint.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(std430, binding = 6) restrict buffer SplatAccumulation { uint accum[]; };
layout(rgba16f, binding = 0) writeonly uniform image2D uColor;
layout(rgba16f, binding = 1) writeonly uniform image2D uNormal;
layout(location = 0) uniform ivec2 uSize;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= uSize.x || p.y >= uSize.y) return;
  uint base = (uint(p.y) * uint(uSize.x) + uint(p.x)) * kSplatStride;
  uint sums[kSplatChannels];
  for (uint c = 0u; c < kSplatChannels; ++c) {
    sums[c] = accum[base + c];
    accum[base + c] = 0u;
  }
  vec4 color, normal;
  resolveSplat(sums, color, normal);
  imageStore(uColor, p, color);
  imageStore(uNormal, p, normal);
}
