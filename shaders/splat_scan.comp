#version 450 core
// ParticleSplat, tiled variant, step 3: one workgroup turns the tiles' counts
// into the start of each tile's list (an exclusive prefix sum), written both
// as the lists' starts and as the scatter's cursors (which it advances).
layout(local_size_x = 1024) in;
layout(std430, binding = 7) restrict buffer TileCounts { uint tileCount[]; };  // in: counts; out: cursors
layout(std430, binding = 9) writeonly restrict buffer TileStarts { uint tileStart[]; };  // tiles + 1 entries
layout(location = 0) uniform uint uTileCount;

shared uint sSum[1024];

void main() {
  uint lid = gl_LocalInvocationIndex;
  uint carry = 0u;
  for (uint base = 0u; base < uTileCount; base += 1024u) {
    uint i = base + lid;
    uint mine = i < uTileCount ? tileCount[i] : 0u;
    sSum[lid] = mine;
    barrier();
    for (uint offset = 1u; offset < 1024u; offset <<= 1u) {
      uint add = lid >= offset ? sSum[lid - offset] : 0u;
      barrier();
      sSum[lid] += add;
      barrier();
    }
    uint start = carry + sSum[lid] - mine;
    if (i < uTileCount) {
      tileStart[i] = start;
      tileCount[i] = start;
    }
    carry += sSum[1023];
    barrier();
  }
  if (lid == 0u) tileStart[uTileCount] = carry;
}
