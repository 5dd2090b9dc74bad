#version 450 core
// ParticleMotionFilter, step 1: the longest motion axis (splat_common.glsl)
// in each kMotionTile-pixel square tile of the view (the resolve's means),
// one workgroup a tile, one invocation a pixel.
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 3) uniform sampler2D uMotion;  // the motion's and its axis's means
layout(rg16f, binding = 4) writeonly uniform image2D uTiles;
layout(location = 0) uniform ivec2 uSize;

shared vec2 sLongest[256];

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  vec2 longest = p.x < uSize.x && p.y < uSize.y ? texelFetch(uMotion, p, 0).zw : vec2(0.0);
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
