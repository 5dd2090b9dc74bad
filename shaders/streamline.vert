#version 450 core
// StreamlineRenderer, drawing: vertex v is end (v & 1) of segment v / 2;
// segment k of line l joins its points k and k + 1 (streamline_trace.comp's
// layout). Segments past a line's end are flagged invalid and dropped.
#include "view_block.glsl"
#include "render_block.glsl"

layout(std430, binding = 4) readonly restrict buffer Points { vec4 points[]; };
layout(std430, binding = 5) readonly restrict buffer Counts { uint counts[]; };
layout(location = 0) uniform int uSteps;

out vec3 vPosition;
out float vColor;
out float vValid;

void main() {
  int segment = gl_VertexID / 2, end = gl_VertexID & 1;
  int line = segment / uSteps, k = segment % uSteps;
  bool valid = uint(k + 1) < counts[line];
  int at = (line * (uSteps + 1) + (valid ? k + end : 0)) * 2;
  vPosition = points[at].xyz;
  vColor = colorCoordinate(0.0, points[at + 1].xyz, points[at].xyz);
  vValid = valid ? 1.0 : 0.0;
#ifdef LINES
  gl_Position = valid ? view.viewProjection * vec4(vPosition, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
#endif
}
