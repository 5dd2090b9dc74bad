#version 450 core
// ParticleSplat, last step: turns each pixel's sums into what ParticleRender's
// blending leaves in the particle buffers (resolveSplat) and zeroes the sums
// for the next view. Reads and writes a pixel's sums (kSplatStride = 8 uints,
// one 32-byte sector) as two uvec4.
#include "render_block.glsl"
#include "splat_common.glsl"
#include "view_block.glsl"
#include "splat_footprint.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(std430, binding = 6) restrict buffer SplatAccumulation { uvec4 accum[]; };
layout(rgba16f, binding = 0) writeonly uniform image2D uColor;
layout(rgba16f, binding = 1) writeonly uniform image2D uNormal;
layout(r16f, binding = 2) writeonly uniform image2D uLight;
layout(location = 0) uniform ivec2 uSize;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= uSize.x || p.y >= uSize.y) return;
  uint base = (uint(p.y) * uint(uSize.x) + uint(p.x)) * 2u;
  uvec4 first = accum[base], second = accum[base + 1u];
  if (first.z == 0u) {  // nothing splatted here (each contribution adds at least 8 to channel 2)
    imageStore(uColor, p, vec4(0.0));
    imageStore(uNormal, p, vec4(0.0));
    imageStore(uLight, p, vec4(0.0));
    return;
  }
  accum[base] = uvec4(0u);
  accum[base + 1u] = uvec4(0u);
  uint sums[kSplatChannels] = uint[](first.x, first.y, first.z, first.w, second.x, second.y);
  vec4 color, normal;
  float light;
  resolveSplat(sums, color, normal, light);
  imageStore(uColor, p, color);
  imageStore(uNormal, p, normal);
  imageStore(uLight, p, vec4(light));
}
