#version 450 core
#include "view_block.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
out vec3 vPosition;
out vec3 vNormal;

void main() {
  vPosition = inPosition;
  vNormal = inNormal;
  gl_Position = view.viewProjection * vec4(inPosition, 1.0);
}
