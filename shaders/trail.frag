#version 450 core
// TrailRenderer: the particle's colour, fading along its trail.
#include "render_block.glsl"
#include "scene_occlusion.glsl"

in float vColor;
in float vAlpha;
out vec4 fragColor;

void main() {
  if (behindScene()) discard;
  if (vAlpha < 1.0 / 512.0) discard;
  fragColor = vec4(colorAt(vColor), vAlpha);
}
