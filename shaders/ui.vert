#version 450 core
// The menu's triangles (Dear ImGui's draw lists), in display pixels.
layout(location = 0) in vec2 inPosition;
layout(location = 1) in vec2 inUv;
layout(location = 2) in vec4 inColor;
layout(location = 0) uniform mat4 uProjection;
out vec2 vUv;
out vec4 vColor;

void main() {
  vUv = inUv;
  vColor = inColor;
  gl_Position = uProjection * vec4(inPosition, 0.0, 1.0);
}
