#version 450 core
// ParticleSplat, step 3: turns each pixel's sums into what ParticleRender's
// blending leaves in the particle buffers (premultiplied colour and normal,
// alpha), and zeroes the sums for the next view. Alpha is exactly "over"'s,
// 1 - prod(1 - alpha_i); colour and normal are the alpha-weighted means times
// it, which is "over"'s result wherever the overlapping particles share a
// colour (weighted blended order-independent transparency otherwise).
#include "render_block.glsl"
#include "splat_common.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
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
  vec4 color = vec4(0.0), normal = vec4(0.0);
  float weight = float(sums[0]);
  if (weight > 0.0) {
    float alpha = 1.0 - exp(-float(sums[2]) / kSplatScale);
    float age = float(sums[1]) / weight;  // alpha-weighted mean age: the mean colour, colour being linear in age
    color = vec4(mix(look.colorBirth.rgb, look.colorDeath.rgb, age) * alpha, alpha);
    normal = vec4(vec3(int(sums[3]), int(sums[4]), int(sums[5])) / weight * alpha, alpha);
  }
  imageStore(uColor, p, color);
  imageStore(uNormal, p, normal);
}
