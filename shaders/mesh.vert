#version 450 core
// Scene props (the helicopter proxy): positions and normals, placed by uModel.
#include "view_block.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 0) uniform mat4 uModel;
out vec3 vNormal;
out vec3 vPosition;

void main() {
  vec4 world = uModel * vec4(inPosition, 1.0);
  vNormal = mat3(uModel) * inNormal;
  vPosition = world.xyz;
  gl_Position = view.viewProjection * world;
}
