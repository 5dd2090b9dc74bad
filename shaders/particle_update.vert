#version 450 core
// ParticleGeoUpdate, particle pass: the vertex stage only hands records on;
// the geometry stage decides their fate.
layout(location = 0) in vec4 inPositionLife;
layout(location = 1) in vec4 inVelocityKind;
out vec4 vPositionLife;
out vec4 vVelocityKind;

void main() {
  vPositionLife = inPositionLife;
  vVelocityKind = inVelocityKind;
}
