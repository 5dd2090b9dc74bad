// The terrain's height at p: the twin of HeightMap::heightAt. Needs sim_block.glsl.

float terrainHeight(vec2 p) {
  ivec2 dims = sim.terrainDims.xy;
  precise vec2 u = clamp((p - sim.terrainMinScale.xy) * sim.terrainMinScale.zw, vec2(0.0), vec2(dims - 1));
  ivec2 i0 = min(ivec2(floor(u)), dims - 2);
  precise vec2 f = u - vec2(i0);
  float h00 = texelFetch(uTerrain, i0, 0).x;
  float h10 = texelFetch(uTerrain, i0 + ivec2(1, 0), 0).x;
  float h01 = texelFetch(uTerrain, i0 + ivec2(0, 1), 0).x;
  float h11 = texelFetch(uTerrain, i0 + ivec2(1, 1), 0).x;
  precise float h0 = h00 + (h10 - h00) * f.x;
  precise float h1 = h01 + (h11 - h01) * f.x;
  precise float h = h0 + (h1 - h0) * f.y;
  return h;
}
