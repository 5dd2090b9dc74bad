#version 450 core
// sandstorm-bench's point-draw ceiling: the particle records as one-pixel points.
layout(location = 0) in vec4 inPositionLife;
layout(location = 1) in vec4 inVelocityKind;
out float vShade;

void main() {
  gl_Position = vec4(inPositionLife.xyz, 1.0);
  gl_PointSize = 1.0;
  vShade = inVelocityKind.w;
}
