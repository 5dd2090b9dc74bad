#version 450 core
// Tests only: the analytic field of the bound EquationBlock at each point.
#define FIELD_EQUATION
#include "field_equation.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; };
layout(std430, binding = 1) writeonly buffer Values { vec4 values[]; };
layout(location = 0) uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  values[i] = vec4(equationAt(points[i].xyz), 0.0);
}
