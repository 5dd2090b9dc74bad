#version 450 core
// The ground of a height map (a flat ground is drawn by scene_background.comp).
#include "view_block.glsl"
#include "render_block.glsl"
#include "shadow_block.glsl"
#include "scene_ground.glsl"

in vec3 vPosition;
in vec3 vNormal;
out vec4 fragColor;

void main() { fragColor = vec4(groundColor(vPosition, normalize(vNormal), fwidth(vPosition.xy)), 1.0); }
