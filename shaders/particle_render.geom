#version 450 core
// ParticleRender: a spherical billboard per particle (thesis 5.1.3), a quad
// turned to face this view's eye. Facing the eye (not the image plane) keeps a
// particle's quad identical on every wall of a CAVE, so particles cross the
// seams between walls unbroken. With motion blur (render.shutter) the quad
// is stretched back along the particle's path over the shutter time, as seen
// from the eye, and the fragment stage averages the puff along it.
#include "view_block.glsl"
#include "render_block.glsl"

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
in vec3 vCenter[];
in float vAge[];
in float vColor[];
in float vLight[];
in vec3 vVelocity[];
out vec2 gCorner;  // from the particle's centre, in radii along gRight and gUp
out vec2 gMotion;  // where the centre was when the shutter opened, negated (radii)
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
  // The path over the shutter time, in the quad's plane.
  vec3 path = vVelocity[0] * look.params.w;
  path -= n * dot(path, n);
  float pathLength = sqrt(dot(path, path));
  float smear = 0.0;  // the path's length in radii
  if (pathLength > 1e-4 * radius) {
    right = path / pathLength;
    up = cross(n, right);
    smear = pathLength / radius;
  }
  const vec2 corners[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(-1, 1), vec2(1, 1));
  for (int i = 0; i < 4; ++i) {
    // x runs from the oldest position's rim (-1 - smear) to the newest's (1).
    gCorner = vec2(corners[i].x > 0.0 ? 1.0 : -1.0 - smear, corners[i].y);
    gMotion = vec2(smear, 0.0);
    gRight = right;
    gUp = up;
    gToEye = n;
    gAge = vAge[0];
    gColor = vColor[0];
    gLight = vLight[0];
    gl_Position = view.viewProjection * vec4(center + radius * (gCorner.x * right + gCorner.y * up), 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
