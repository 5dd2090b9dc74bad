// The simulation's uniform block: the twin of contexts/particles/sim_block.h.

const int kMaxEmitters = 16;
const int kMotionTracer = 0, kMotionForce = 1, kMotionDrag = 2;
const int kEuler = 0, kRK2 = 1, kRK4 = 2;
const int kBoundaryKill = 0, kBoundaryClamp = 1, kBoundaryWrap = 2;
const int kShapeBox = 0, kShapeSphere = 1, kShapeDisc = 2, kShapePoint = 3;

struct EmitterBlock {
  vec4 position;     // xyz
  vec4 size;         // width, depth, height, radius
  vec4 life;         // lifetime, lifetime variance, spread
  vec4 velocity;     // xyz
  ivec4 shapeCount;  // shape, granted count, first slot
};

const int kMaxObstacles = 16;

struct ObstacleBlock {
  vec4 positionRadius;  // centre, w: radius (sphere, cylinder)
  vec4 halfSize;        // a box's half extent (a sphere's x: R^3 / 2), w: a cylinder's half height
  vec4 velocity;        // xyz, w: restitution
  ivec4 shapeFlow;      // shape, flow (1: the flow goes around it)
};

layout(std140, binding = 0) uniform SimBlock {
  vec4 fieldMin;
  vec4 fieldIndexScale;
  ivec4 fieldDims;        // xyz, w: 1 when there is a field
  vec4 domainMin;
  vec4 domainMax;
  vec4 placementOffset;   // xyz, w: scale
  vec4 placementRotation[3];
  vec4 gravity;           // xyz, w: 1 / drag time
  vec4 stepParams;        // dt, field strength, restitution, 1 / scale
  ivec4 modes;            // motion, integrator, boundary, ground collision
  uvec4 frameSeed;        // frame, seed lo, seed hi, emitter count
  vec4 terrainMinScale;   // min xy, index scale xy
  ivec4 terrainDims;      // xy, z: 1 when there is terrain
  vec4 fieldBlend;        // x: weight towards the next frame, y: 1 when there is one,
                          // z: 1 when a frame has a validity mask (in w / alpha)
  EmitterBlock emitters[kMaxEmitters];
  vec4 expression;        // x: simulated seconds before this step (a field expression's t)
  ivec4 obstacleCount;    // x: obstacles below (collisionShapes)
  ObstacleBlock obstacles[kMaxObstacles];
  vec4 sparseIndexMin;    // a sparse grid's index box, widened (field_sparse.glsl)
  vec4 sparseIndexMax;
} sim;

// The field's grid (GpuField), x fastest: FIELD_BUFFER programs (the compute
// backend) read it from storage buffers of vec4 (xyz, w: valid),
// FIELD_BUFFER_HALF ones from buffers of four halves a point (the same
// four, unpacked: exact), the others from textures. gridPoint(i) and
// gridPointNext(i): point i of the current and the next frame.
#ifdef FIELD_BUFFER_HALF
#define FIELD_BUFFER
layout(std430, binding = 14) readonly restrict buffer FieldGrid { uvec2 fieldGrid[]; };  // x, y | z, valid
layout(std430, binding = 15) readonly restrict buffer FieldGridNext { uvec2 fieldGridNext[]; };
vec4 gridPoint(int i) {
  uvec2 h = fieldGrid[i];
  return vec4(unpackHalf2x16(h.x), unpackHalf2x16(h.y));
}
vec4 gridPointNext(int i) {
  uvec2 h = fieldGridNext[i];
  return vec4(unpackHalf2x16(h.x), unpackHalf2x16(h.y));
}
#elif defined(FIELD_BUFFER)
layout(std430, binding = 14) readonly restrict buffer FieldGrid { vec4 fieldGrid[]; };
layout(std430, binding = 15) readonly restrict buffer FieldGridNext { vec4 fieldGridNext[]; };
vec4 gridPoint(int i) { return fieldGrid[i]; }
vec4 gridPointNext(int i) { return fieldGridNext[i]; }
#endif
#ifndef FIELD_BUFFER
layout(binding = 0) uniform sampler3D uField;      // RGB32F (RGBA32F: alpha valid), texelFetch only
layout(binding = 2) uniform sampler3D uFieldNext;  // a time-varying field's next frame
#endif
layout(binding = 1) uniform sampler2D uTerrain;    // R32F heights

struct Particle {
  vec4 positionLife;
  vec4 velocityKind;
};
