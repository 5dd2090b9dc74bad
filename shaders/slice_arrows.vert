#version 450 core
// SliceRenderer: arrow glyphs on the slice (core/flow/slice_arrows.h), lines in
// the particles' coordinates, pulled a hair toward the eye so they win the
// depth test against the slice they lie in.
#include "view_block.glsl"

layout(location = 0) in vec3 inPosition;

void main() {
  gl_Position = view.viewProjection * vec4(inPosition, 1.0);
  gl_Position.z -= 2e-4 * gl_Position.w;
}
