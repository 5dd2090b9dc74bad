#version 450 core
// Scene props (the helicopter, the obstacles, the probe's marker), lit by the
// scene light through the dust's shadow; uColor.a < 1 for a blended one.
#include "render_block.glsl"
#include "shadow_block.glsl"

layout(location = 1) uniform vec4 uColor;
in vec3 vNormal;
in vec3 vPosition;
out vec4 fragColor;

void main() {
  vec3 direct = max(dot(normalize(vNormal), look.lightDirection.xyz), 0.0) * lightTransmittance(vPosition) * look.light.rgb;
  fragColor = vec4(uColor.rgb * (0.35 + 0.65 * direct), uColor.a);  // alpha < 1: blended props
}
