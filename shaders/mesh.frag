#version 450 core
#include "render_block.glsl"

layout(location = 1) uniform vec4 uColor;
in vec3 vNormal;
out vec4 fragColor;

void main() {
  float diffuse = max(dot(normalize(vNormal), look.lightDirection.xyz), 0.0);
  fragColor = vec4(uColor.rgb * (0.35 + 0.65 * diffuse), 1.0);
}
