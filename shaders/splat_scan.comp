#version 450 core
// ParticleSplat, tiled variant, step 3: one workgroup turns the tiles' counts
// into where each tile's list starts and where its chunks start (exclusive
// prefix sums of the counts and of ceil(count / uChunk)), writes the
// chunk pass's dispatch size, and zeroes the counts for the next view.
#include "splat_common.glsl"

layout(local_size_x = 1024) in;
layout(std430, binding = 7) restrict buffer TileCounts { uint tileCount[]; };
layout(std430, binding = 9) writeonly restrict buffer TileStarts { uint tileStart[]; };    // tiles + 1
layout(std430, binding = 11) writeonly restrict buffer ChunkStarts { uint chunkStart[]; };  // tiles + 1
layout(std430, binding = 12) writeonly restrict buffer ChunkDispatch {
  uvec4 dispatch;
  uint chunks;
} chunkArgs;
layout(location = 0) uniform uint uTileCount;
layout(location = 1) uniform uint uChunk;  // entries a chunk

const uint kGroupsPerRow = 32768u;

shared uvec2 sSum[1024];

void main() {
  uint lid = gl_LocalInvocationIndex;
  uvec2 carry = uvec2(0u);
  for (uint base = 0u; base < uTileCount; base += 1024u) {
    uint i = base + lid;
    uint n = i < uTileCount ? tileCount[i] : 0u;
    uvec2 mine = uvec2(n, (n + uChunk - 1u) / uChunk);
    sSum[lid] = mine;
    barrier();
    for (uint offset = 1u; offset < 1024u; offset <<= 1u) {
      uvec2 add = lid >= offset ? sSum[lid - offset] : uvec2(0u);
      barrier();
      sSum[lid] += add;
      barrier();
    }
    uvec2 start = carry + sSum[lid] - mine;
    if (i < uTileCount) {
      tileStart[i] = start.x;
      chunkStart[i] = start.y;
      tileCount[i] = 0u;
    }
    carry += sSum[1023];
    barrier();
  }
  if (lid == 0u) {
    tileStart[uTileCount] = carry.x;
    chunkStart[uTileCount] = carry.y;
    uint chunks = carry.y;
    chunkArgs.dispatch = uvec4(min(chunks, kGroupsPerRow), (chunks + kGroupsPerRow - 1u) / kGroupsPerRow, 1u, 0u);
    chunkArgs.chunks = chunks;
  }
}
