#version 450 core
// sandstorm-bench's transform-feedback ceiling: records in, records out, nothing else.
layout(location = 0) in vec4 inPositionLife;
layout(location = 1) in vec4 inVelocityKind;
out vec4 outPositionLife;
out vec4 outVelocityKind;

void main() {
  outPositionLife = inPositionLife;
  outVelocityKind = inVelocityKind;
}
