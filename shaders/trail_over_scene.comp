#version 450 core
// ParticleSplat, trails in a view that draws billboards: each pixel's trail
// sums (splat_common.glsl's channels 6 and 7) blended over the scene's
// colour as a trail's GL line was, unlit: the mean colour coordinate's
// colour, the opacity of the summed optical depth. Zeroes the sums for the
// next view.
#include "render_block.glsl"
#include "splat_common.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(std430, binding = 6) restrict buffer SplatAccumulation { uvec4 accum[]; };
layout(rgba8, binding = 0) restrict uniform image2D uScene;
layout(location = 0) uniform ivec2 uSize;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= uSize.x || p.y >= uSize.y) return;
  uint index = (uint(p.y) * uint(uSize.x) + uint(p.x)) * 2u + 1u;  // channels 4..7
  uvec2 trail = accum[index].zw;
  if (trail.x == 0u) return;
  accum[index] = uvec4(0u);
  float alpha = 1.0 - exp(-float(trail.x) / kSplatScale);
  vec3 colour = colorAt(float(trail.y) / float(trail.x));
  vec4 scene = imageLoad(uScene, p);
  imageStore(uScene, p, vec4(mix(scene.rgb, colour, alpha), scene.a));
}
