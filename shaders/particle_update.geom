#version 450 core
// ParticleGeoUpdate, particle pass (thesis 5.1.1-5.1.2): a dead particle emits
// nothing, which frees its slot; a live one advances through the field and is
// written, through transform feedback, into the other buffer.
#include "sim_block.glsl"
#include "particle_physics.glsl"

layout(points) in;
layout(points, max_vertices = 1) out;
in vec4 vPositionLife[];
in vec4 vVelocityKind[];
out vec4 outPositionLife;
out vec4 outVelocityKind;
#ifdef TRAILS
// The input record each survivor came from (ParticleTrails moves its trail
// along): the draw's first record plus the primitive's index in the draw.
uniform uint uSourceBase;
flat out uint outSource;
#endif

void main() {
  Particle p;
  p.positionLife = vPositionLife[0];
  p.velocityKind = vVelocityKind[0];
  if (!advance(p)) return;
  outPositionLife = p.positionLife;
  outVelocityKind = p.velocityKind;
#ifdef TRAILS
  outSource = uSourceBase + uint(gl_PrimitiveIDIn);
#endif
  EmitVertex();
  EndPrimitive();
}
