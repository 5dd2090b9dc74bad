#version 450 core
// ParticleTrails: after an update, record o's trail ring (the last K
// positions, ring slot `uHead` the newest) is its source record's ring moved
// along, with the particle's new position at the head; a newborn (record <
// uBorn, or every record after the rings were made) starts a ring holding only
// its birth position. w: 1 for a slot that holds a position, 0 not yet.
// The live records: trail_dispatch.comp's, from the compute backend's
// control block or the transform-feedback backend's survivors plus newborn.

// One invocation a slot, so that a warp reads and writes two whole rings of
// consecutive memory.
layout(local_size_x = 256) in;
layout(std430, binding = 2) readonly restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 6) readonly restrict buffer TrailSource { uint trailSource[]; };
layout(std430, binding = 7) readonly restrict buffer InRing { vec4 inRing[]; };
layout(std430, binding = 8) writeonly restrict buffer OutRing { vec4 outRing[]; };
layout(std430, binding = 13) readonly restrict buffer Dispatch { uvec4 dispatch; };  // trail_dispatch.comp's

layout(location = 1) uniform uint uBorn;
layout(location = 2) uniform int uLength;
layout(location = 3) uniform int uHead;
layout(location = 4) uniform bool uFresh;

void main() {
  uint slot = (gl_WorkGroupID.y * dispatch.x + gl_WorkGroupID.x) * 256u + gl_LocalInvocationIndex;
  uint o = slot / uint(uLength);
  int k = int(slot % uint(uLength));
  if (o >= dispatch.w) return;
  if (k == uHead)
    outRing[slot] = vec4(positionLife[o].xyz, 1.0);
  else if (uFresh || o < uBorn)
    outRing[slot] = vec4(positionLife[o].xyz, 0.0);
  else
    outRing[slot] = inRing[trailSource[o] * uint(uLength) + uint(k)];
}
