#version 450 core
// ParticleRender: particles from the update's buffers. Billboards are built by
// the geometry stage; points are sized here to their projected diameter.
#include "view_block.glsl"
#include "render_block.glsl"
#include "shadow_block.glsl"

#ifdef SORTED
// render.order = sorted: record sortedIndex[gl_VertexID], back to front (ParticleSort).
layout(std430, binding = 0) readonly restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 1) readonly restrict buffer VelocityKind { vec4 velocityKind[]; };
layout(std430, binding = 2) readonly restrict buffer SortedIndex { uint sortedIndex[]; };
#else
layout(location = 0) in vec4 inPositionLife;
layout(location = 1) in vec4 inVelocityKind;
#endif
out vec3 vCenter;
out float vAge;    // 0 at birth, 1 at death
out float vColor;  // the colour map's coordinate
out float vLight;  // the share of the light that reaches it through the dust
out vec3 vVelocity;

void main() {
#ifdef SORTED
  uint record = sortedIndex[gl_VertexID];
  vec4 inPositionLife = positionLife[record], inVelocityKind = velocityKind[record];
#endif
  vCenter = inPositionLife.xyz;
  vAge = clamp(1.0 - inPositionLife.w / max(inVelocityKind.w, 1e-6), 0.0, 1.0);
  vColor = colorCoordinate(vAge, inVelocityKind.xyz, inPositionLife.xyz);
  vLight = lightTransmittance(vCenter);
  vVelocity = inVelocityKind.xyz;
#ifdef POINTS
  gl_Position = view.viewProjection * vec4(vCenter, 1.0);
  float pixels = look.params.x * view.viewport.w * view.projection[1][1] / (2.0 * max(gl_Position.w, 1e-4));
  gl_PointSize = clamp(pixels, 1.0, 64.0);
#endif
}
