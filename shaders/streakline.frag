#version 450 core
// StreaklineRenderer: the colour map at the point, fading along the line.
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
