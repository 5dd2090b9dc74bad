#version 450 core
// ParticleComputeUpdate, after the update: every live record of the output
// set out of the obstacles (keepOutOfObstacles, the last step of advance()).
// A pass of its own because the push-out's code in the update kernel cost it
// occupancy (an H100's update at 10^7 with two obstacles: 1.46 ms with it
// inside, 0.89 without; docs/PERFORMANCE.md). The same operations on the same
// records in the same order as advance() would do them, so the result is the
// CPU reference's bit for bit. Only records inside an obstacle read their
// velocity and write.
#define OBSTACLES
#include "sim_block.glsl"
#include "particle_control.glsl"
#include "terrain_height.glsl"
#include "obstacles.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 2) restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 3) restrict buffer VelocityKind { vec4 velocityKind[]; };
layout(location = 0) uniform int uSet;  // the output set, whose count the update wrote

void main() {
  uint count = ctl.count[uSet];
  uint stride = gl_NumWorkGroups.x * 256u;
  bool ground = sim.modes.w != 0 && sim.terrainDims.z != 0;
  for (uint i = gl_GlobalInvocationID.x; i < count; i += stride) {
    vec4 pl = positionLife[i];
    vec3 x = pl.xyz;
    bool clear = true;
    for (int k = 0; k < sim.obstacleCount.x; ++k)
      clear = clear && clearOf(k, x);
    if (clear) continue;  // keepOutOfObstacles would leave it as it is
    vec4 vk = velocityKind[i];
    vec3 v = vk.xyz;
    keepOutOfObstacles(x, v, ground);
    positionLife[i] = vec4(x, pl.w);
    velocityKind[i] = vec4(v, vk.w);
  }
}
