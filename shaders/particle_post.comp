#version 450 core
// ParticlePost into an offscreen wall's image (particle_post.glsl), by
// compute: the raster pass's fill of every pixel took 0.17-0.23 ms of a
// 1920x1080 view on an H100.
#include "view_block.glsl"
#include "render_block.glsl"
#include "shadow_block.glsl"
#include "light_scattering.glsl"
#include "particle_post.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba8, binding = 0) writeonly uniform image2D uOutput;
layout(location = 0) uniform ivec2 uOrigin;  // this view's corner in the image

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(view.viewport.z) || p.y >= int(view.viewport.w)) return;
  imageStore(uOutput, p + uOrigin, compositeAt(p));
}
