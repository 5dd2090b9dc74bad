#version 450 core
// ParticleComputeUpdate, step 2: invocation g writes the g-th newborn of the
// update at record g; emitters' newborn follow one another in emitter order,
// as in the emission pass of the transform-feedback path (particle_emit.geom).
#include "rng.glsl"
#include "sim_block.glsl"
#include "particle_birth.glsl"
#ifdef OBSTACLES
#include "terrain_height.glsl"
#include "obstacles.glsl"
#endif

layout(local_size_x = 256) in;
layout(std430, binding = 2) writeonly restrict buffer OutPositionLife { vec4 outPositionLife[]; };
layout(std430, binding = 3) writeonly restrict buffer OutVelocityKind { vec4 outVelocityKind[]; };
layout(location = 1) uniform uint uBorn;

void main() {
  uint g = gl_GlobalInvocationID.x;
  if (g >= uBorn) return;
  int count = int(sim.frameSeed.w);
  int e = 0;
  uint first = 0u;
  while (e + 1 < count && g >= first + uint(sim.emitters[e].shapeCount.y)) {
    first += uint(sim.emitters[e].shapeCount.y);
    ++e;
  }
  Particle p = birth(e, g - first);
#ifdef OBSTACLES
  settleNewborn(p);
#endif
  outPositionLife[g] = p.positionLife;
  outVelocityKind[g] = p.velocityKind;
}
