#version 450 core
// SliceRenderer: arrow glyphs, dark so they read on every colour map.
#include "scene_occlusion.glsl"
layout(location = 0) out vec4 outColor;

void main() {
  if (behindScene()) discard;
  outColor = vec4(0.06, 0.06, 0.06, 1.0);
}
