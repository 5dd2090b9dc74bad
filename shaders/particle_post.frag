#version 450 core
// ParticlePost into a window's framebuffer (particle_post.glsl).
#include "view_block.glsl"
#include "render_block.glsl"
#include "shadow_block.glsl"
#include "light_scattering.glsl"
#include "particle_post.glsl"

layout(location = 0) uniform ivec2 uOrigin;  // this view's corner in the destination

out vec4 fragColor;

void main() { fragColor = compositeAt(ivec2(gl_FragCoord.xy) - uOrigin); }
