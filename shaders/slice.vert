#version 450 core
// SliceRenderer: the slice polygon, a triangle fan of up to 6 corners.
#include "view_block.glsl"

layout(location = 0) uniform vec4 uCorners[6];
out vec3 vPosition;

void main() {
  vPosition = uCorners[gl_VertexID].xyz;
  gl_Position = view.viewProjection * vec4(vPosition, 1.0);
}
