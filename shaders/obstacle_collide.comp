#version 450 core
// ParticleComputeUpdate, after the update: the output set's records that the
// update listed as not clear of some obstacle (OBSTACLE_LIST) put out of the
// obstacles (keepOutOfObstacles, the last step of advance()); every other
// record is clear, and keepOutOfObstacles would leave it as it is.
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
layout(std430, binding = 8) readonly restrict buffer CollideList {
  uint collideCount;
  uint collideIndex[];
};

void main() {
  uint count = collideCount;
  uint stride = gl_NumWorkGroups.x * 256u;
  bool ground = sim.modes.w != 0 && sim.terrainDims.z != 0;
  for (uint j = gl_GlobalInvocationID.x; j < count; j += stride) {
    uint i = collideIndex[j];
    vec4 pl = positionLife[i];
    vec3 x = pl.xyz;
    vec4 vk = velocityKind[i];
    vec3 v = vk.xyz;
    keepOutOfObstacles(x, v, ground);
    positionLife[i] = vec4(x, pl.w);
    velocityKind[i] = vec4(v, vk.w);
  }
}
