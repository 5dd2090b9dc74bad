#version 450 core
// StreamlineRenderer: the colour map at the line's colour coordinate; ribbons
// shaded as a tube seen side on (brightest along the middle).
#include "render_block.glsl"

#ifdef LINES
in float vColor;
in float vValid;
#else
in float gColor;
in float gAcross;
#endif
out vec4 fragColor;

void main() {
#ifdef LINES
  if (vValid < 0.5) discard;
  fragColor = vec4(colorAt(vColor), 1.0);
#else
  float round = sqrt(max(1.0 - gAcross * gAcross, 0.0));
  fragColor = vec4(colorAt(gColor) * (0.45 + 0.55 * round), 1.0);
#endif
}
