#version 450 core
// ParticleSplat, tiled variant, steps 2 and 4: each invocation finds the
// tiles of kSplatTile x kSplatTile pixels one particle covers. COUNT: adds one
// to each tile's count. Otherwise (scatter): takes a slot in each tile's list
// (offsets from splat_scan.comp) and writes the particle's index there.
#include "view_block.glsl"
#include "render_block.glsl"
#include "splat_common.glsl"
#include "splat_footprint.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 1) readonly restrict buffer VelocityKind { vec4 velocityKind[]; };
layout(std430, binding = 5) readonly buffer Dispatch {
  uvec4 dispatch;
  uint count;
} args;
layout(std430, binding = 7) restrict buffer TileCounts { uint tileCount[]; };  // COUNT: counts; else: cursors
layout(std430, binding = 8) writeonly restrict buffer TileLists { uint tileList[]; };
layout(location = 0) uniform ivec2 uTiles;       // tiles across, down
layout(location = 1) uniform uint uListCapacity;  // entries tileList holds

void main() {
  uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 256u + gl_LocalInvocationIndex;
  if (i >= args.count) return;
  Splat s;
  if (!makeSplat(positionLife[i], velocityKind[i], s)) return;
  ivec2 t0 = s.lo / kSplatTile, t1 = s.hi / kSplatTile;
  for (int ty = t0.y; ty <= t1.y; ++ty)
    for (int tx = t0.x; tx <= t1.x; ++tx) {
      uint tile = uint(ty * uTiles.x + tx);
#ifdef COUNT
      atomicAdd(tileCount[tile], 1u);
#else
      uint slot = atomicAdd(tileCount[tile], 1u);
      if (slot < uListCapacity) tileList[slot] = i;
#endif
    }
}
