#version 450 core
// TrailRenderer: vertex v is end (v & 1) of segment v / 2; segment j of
// record o joins its trail's positions j and j + 1 back from the newest
// (ring slots head - j and head - j - 1). Segments past the live count or the
// trail's start are dropped (outside the clip volume).
#include "view_block.glsl"
#include "render_block.glsl"

layout(std430, binding = 0) readonly restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 1) readonly restrict buffer VelocityKind { vec4 velocityKind[]; };
layout(std430, binding = 4) readonly restrict buffer Count { uint counts[]; };
layout(std430, binding = 7) readonly restrict buffer Ring { vec4 ring[]; };
layout(location = 0) uniform int uLength;
layout(location = 1) uniform int uHead;
layout(location = 2) uniform uint uCountIndex;  // the live count: counts[uCountIndex] + uCountAdd
layout(location = 3) uniform uint uCountAdd;

out float vColor;
out float vAlpha;

void main() {
  int segments = uLength - 1;
  int segment = gl_VertexID / 2, end = gl_VertexID & 1;
  uint o = uint(segment / segments);
  int j = segment % segments;
  int newer = (uHead - j + uLength) % uLength, older = (uHead - j - 1 + uLength) % uLength;
  bool valid = o < counts[uCountIndex] + uCountAdd && ring[o * uint(uLength) + uint(older)].w > 0.5;
  vec4 slot = ring[o * uint(uLength) + uint(end == 0 ? newer : older)];
  vec4 pl = valid ? positionLife[o] : vec4(0.0), vk = valid ? velocityKind[o] : vec4(1.0);
  float age = clamp(1.0 - pl.w / max(vk.w, 1e-6), 0.0, 1.0);
  vColor = colorCoordinate(age, vk.xyz, pl.xyz);
  // Fading towards the trail's end, from the particle's own opacity.
  float along = (float(j + end)) / float(segments);
  vAlpha = mix(look.colorBirth.a, look.colorDeath.a, age) * (1.0 - along);
  gl_Position = valid ? view.viewProjection * vec4(slot.xyz, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
}
