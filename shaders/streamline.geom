#version 450 core
// StreamlineRenderer: a segment as a ribbon `uWidth` metres wide, turned to
// face the eye (a tube's silhouette); the fragment shader shades it round.
#include "view_block.glsl"

layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
layout(location = 1) uniform float uWidth;
in vec3 vPosition[];
in float vColor[];
in float vValid[];
out float gColor;
out float gAcross;  // -1 .. 1 across the ribbon

void main() {
  if (vValid[0] < 0.5) return;
  vec3 a = vPosition[0], b = vPosition[1];
  vec3 along = b - a;
  vec3 toEye = view.eye.xyz - 0.5 * (a + b);
  vec3 side = cross(along, toEye);
  if (dot(side, side) < 1e-20) return;
  side = normalize(side) * (0.5 * uWidth);
  for (int i = 0; i < 4; ++i) {
    vec3 p = (i < 2 ? a : b) + ((i & 1) == 0 ? -side : side);
    gColor = i < 2 ? vColor[0] : vColor[1];
    gAcross = (i & 1) == 0 ? -1.0 : 1.0;
    gl_Position = view.viewProjection * vec4(p, 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
