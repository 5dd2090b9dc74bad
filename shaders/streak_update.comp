#version 450 core
// StreaklineRenderer: one frame of the streak points (StreaklineReference,
// core/flow/streaklines.cpp): slot uHead of emitter e's ring is its newly
// released point; every other valid point moves as a particle (advance()).
// Ring slot: two vec4, position (w: 1 valid) and velocity.
#include "sim_block.glsl"
#include "particle_physics.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 11) restrict buffer Ring { vec4 ring[]; };
layout(location = 0) uniform int uLength;
layout(location = 1) uniform int uHead;
layout(location = 2) uniform uint uReleasing;  // bit e: emitter e releases

void main() {
  int slot = int(gl_GlobalInvocationID.x);
  if (slot >= 16 * uLength) return;
  int e = slot / uLength, k = slot % uLength;
  uint at = uint(slot) * 2u;
  if (k == uHead) {
    bool releases = (uReleasing & (1u << uint(e))) != 0u;
    ring[at] = vec4(sim.emitters[e].position.xyz, releases ? 1.0 : 0.0);
    ring[at + 1u] = vec4(sim.emitters[e].velocity.xyz, 0.0);
    return;
  }
  vec4 x = ring[at];
  if (x.w < 0.5) return;
  Particle p;
  p.positionLife = vec4(x.xyz, 1e30);
  p.velocityKind = vec4(ring[at + 1u].xyz, 1e30);
  bool alive = advance(p);
  ring[at] = vec4(p.positionLife.xyz, alive ? 1.0 : 0.0);
  ring[at + 1u] = vec4(p.velocityKind.xyz, 0.0);
}
