#version 450 core
// ParticleGeoUpdate, emission pass: the emitter records emit their newborn
// particles (thesis 5.1.1). Emitters live in the uniform block, not in the
// particle buffer (the thesis's own future-work note), and each one's count,
// granted by the main context's Reeves draw and the emission budget, is spread
// over slots of kSlotSize particles so no invocation outgrows the geometry
// stage's output limit.
#include "rng.glsl"
#include "sim_block.glsl"
#include "particle_birth.glsl"
#ifdef OBSTACLES
#include "terrain_height.glsl"
#include "obstacles.glsl"
#endif

#ifndef SLOT_SIZE
#define SLOT_SIZE 64
#endif
const int kSlotSize = SLOT_SIZE;

layout(points) in;
layout(points, max_vertices = SLOT_SIZE) out;
flat in int vSlot[];
out vec4 outPositionLife;
out vec4 outVelocityKind;

void main() {
  int slot = vSlot[0];
  int e = 0;
  int count = int(sim.frameSeed.w);
  while (e + 1 < count && slot >= sim.emitters[e + 1].shapeCount.z) ++e;
  int first = (slot - sim.emitters[e].shapeCount.z) * kSlotSize;
  int last = min(first + kSlotSize, sim.emitters[e].shapeCount.y);
  for (int k = first; k < last; ++k) {
    Particle p = birth(e, uint(k));
#ifdef OBSTACLES
    settleNewborn(p);
#endif
    outPositionLife = p.positionLife;
    outVelocityKind = p.velocityKind;
    EmitVertex();
    EndPrimitive();
  }
}
