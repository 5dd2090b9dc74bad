#version 450 core
// ParticleMotionFilter, step 1: the longest motion axis (splat_common.glsl)
// in each kMotionTile-pixel square tile of the view (particle_splat_resolve.comp),
// so the filter knows what may smear into a pixel from up to one tile away
// (a smear is at most kMaxSmear = 48 pixels: splat_footprint.glsl).
// One workgroup of 16x16 invocations a tile, each taking 3x3 pixels.
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 3) uniform sampler2D uMotion;  // the motion's and its axis's means
layout(rg16f, binding = 4) writeonly uniform image2D uTiles;
layout(location = 0) uniform ivec2 uSize;

const int kMotionTile = 48;
shared vec2 sLongest[256];

void main() {
  ivec2 origin = ivec2(gl_WorkGroupID.xy) * kMotionTile + ivec2(gl_LocalInvocationID.xy) * 3;
  vec2 longest = vec2(0.0);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) {
      ivec2 p = origin + ivec2(x, y);
      if (p.x >= uSize.x || p.y >= uSize.y) continue;
      vec2 m = texelFetch(uMotion, p, 0).zw;
      if (dot(m, m) > dot(longest, longest)) longest = m;
    }
  uint lid = gl_LocalInvocationIndex;
  sLongest[lid] = longest;
  barrier();
  for (uint span = 128u; span > 0u; span >>= 1) {
    if (lid < span) {
      vec2 other = sLongest[lid + span];
      if (dot(other, other) > dot(sLongest[lid], sLongest[lid])) sLongest[lid] = other;
    }
    barrier();
  }
  if (lid == 0u) imageStore(uTiles, ivec2(gl_WorkGroupID.xy), vec4(sLongest[0], 0.0, 0.0));
}
