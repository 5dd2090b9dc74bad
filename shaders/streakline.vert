#version 450 core
// StreaklineRenderer, drawing: segment j of emitter e joins its points j and
// j + 1 back from the newest release (ring slots head - j, head - j - 1);
// segments with a point not (or no longer) valid are dropped. Drawn with
// streakline.frag: the colour map, fading towards the oldest point.
#include "view_block.glsl"
#include "render_block.glsl"

layout(std430, binding = 11) readonly restrict buffer Ring { vec4 ring[]; };
layout(location = 0) uniform int uLength;
layout(location = 1) uniform int uHead;

out float vColor;
out float vAlpha;

void main() {
  int segments = uLength - 1;
  int segment = gl_VertexID / 2, end = gl_VertexID & 1;
  int e = segment / segments, j = segment % segments;
  int newer = (uHead - j + uLength) % uLength, older = (uHead - j - 1 + uLength) % uLength;
  uint a = uint(e * uLength + newer) * 2u, b = uint(e * uLength + older) * 2u;
  bool valid = ring[a].w > 0.5 && ring[b].w > 0.5;
  uint at = end == 0 ? a : b;
  vec3 x = ring[at].xyz;
  float along = float(j + end) / float(segments);
  vColor = colorCoordinate(along, ring[at + 1u].xyz, x);
  vAlpha = valid ? mix(look.colorBirth.a, look.colorDeath.a, along) * (1.0 - 0.7 * along) : 0.0;
  gl_Position = valid ? view.viewProjection * vec4(x, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
}
