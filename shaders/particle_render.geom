#version 450 core
// ParticleRender: a spherical billboard per particle (thesis 5.1.3), a quad
// turned to face this view's eye. Facing the eye (not the image plane) keeps a
// particle's quad identical on every wall of a CAVE, so particles cross the
// seams between walls unbroken.
#include "view_block.glsl"
#include "render_block.glsl"

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
in vec3 vCenter[];
in float vAge[];
in float vColor[];
in float vLight[];
out vec2 gCorner;  // -1..1 across the quad
out vec3 gRight;
out vec3 gUp;
out vec3 gToEye;
out float gAge;
out float gColor;
out float gLight;

void main() {
  vec3 center = vCenter[0];
  vec3 toEye = view.eye.xyz - center;
  float distance = length(toEye);
  if (distance < 1e-4) return;
  vec3 n = toEye / distance;
  vec3 worldUp = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(0.0, 1.0, 0.0);
  vec3 right = normalize(cross(worldUp, n));
  vec3 up = cross(n, right);
  float radius = 0.5 * look.params.x;
  const vec2 corners[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(-1, 1), vec2(1, 1));
  for (int i = 0; i < 4; ++i) {
    gCorner = corners[i];
    gRight = right;
    gUp = up;
    gToEye = n;
    gAge = vAge[0];
    gColor = vColor[0];
    gLight = vLight[0];
    gl_Position = view.viewProjection * vec4(center + radius * (corners[i].x * right + corners[i].y * up), 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
