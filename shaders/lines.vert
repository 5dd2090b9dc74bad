#version 450 core
#include "view_block.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 0) uniform mat4 uModel;

void main() { gl_Position = view.viewProjection * uModel * vec4(inPosition, 1.0); }
