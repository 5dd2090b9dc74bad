#version 450 core
// The ground: sand lit by the scene light, with a one-metre grid so scale and
// depth read at a glance. It receives the dust's shadow (render.shadows).
#include "view_block.glsl"
#include "render_block.glsl"
#include "shadow_block.glsl"

in vec3 vPosition;
in vec3 vNormal;
out vec4 fragColor;

void main() {
  vec3 n = normalize(vNormal);
  vec3 direct = max(dot(n, look.lightDirection.xyz), 0.0) * lightTransmittance(vPosition) * look.light.rgb;
  vec3 sand = vec3(0.76, 0.66, 0.50);
  vec2 cell = abs(fract(vPosition.xy + 0.5) - 0.5) / fwidth(vPosition.xy);
  float line = 1.0 - clamp(min(cell.x, cell.y), 0.0, 1.0);
  float distance = length(vPosition - view.eye.xyz);
  line *= clamp(1.0 - distance / 40.0, 0.0, 1.0);
  vec3 color = sand * (0.45 + 0.55 * direct);
  color = mix(color, color * 0.7, line * 0.6);
  fragColor = vec4(color, 1.0);
}
