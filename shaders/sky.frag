#version 450 core
// The scene's background: a sky gradient by view direction.
#include "view_block.glsl"

in vec2 vNdc;
out vec4 fragColor;

void main() {
  vec4 far = view.inverseViewProjection * vec4(vNdc, 1.0, 1.0);
  vec3 dir = normalize(far.xyz / far.w - view.eye.xyz);
  float h = clamp(dir.z, -1.0, 1.0);
  vec3 horizon = vec3(0.86, 0.80, 0.72), zenith = vec3(0.36, 0.55, 0.82), below = vec3(0.45, 0.40, 0.35);
  vec3 sky = h >= 0.0 ? mix(horizon, zenith, pow(h, 0.6)) : mix(horizon, below, pow(-h, 0.5));
  fragColor = vec4(sky, 1.0);
}
