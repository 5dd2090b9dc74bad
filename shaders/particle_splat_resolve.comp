#version 450 core
// ParticleSplat, last step: turns each pixel's sums into what ParticleRender's
// blending leaves in the particle buffers (resolveSplat) and zeroes the
// full-resolution sums for the next view (ParticleSplat clears the coarser
// levels', which many pixels read). Reads a pixel's sums (kSplatStride = 8
// uints, one 32-byte sector) as two uvec4; a coarser level's (render.
// splat_detail) bilinearly between the four level pixels around it.
#include "render_block.glsl"
#include "splat_common.glsl"
#include "view_block.glsl"
#include "splat_footprint.glsl"
#include "splat_occupied.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(std430, binding = 6) restrict buffer SplatAccumulation { uvec4 accum[]; };
layout(rgba16f, binding = 0) writeonly uniform image2D uColor;
layout(rgba16f, binding = 1) writeonly uniform image2D uNormal;
layout(r16f, binding = 2) writeonly uniform image2D uLight;
layout(location = 0) uniform ivec2 uSize;

// Adds `weight` times a pixel's sums (its two uvec4).
void addSums(uvec4 first, uvec4 second, float weight, inout float sums[kSplatChannels]) {
  sums[0] += weight * float(first.x);
  sums[1] += weight * float(first.y);
  sums[2] += weight * float(first.z);
  sums[3] += weight * float(int(first.w));
  sums[4] += weight * float(int(second.x));
  sums[5] += weight * float(int(second.y));
}
void addSums(uint index, float weight, inout float sums[kSplatChannels]) {
  addSums(accum[index * 2u], accum[index * 2u + 1u], weight, sums);
}

// Adds the trails' two sums at view pixel p (splat_common.glsl): their
// optical depth is their weight and their opacity, and their normal faces
// the eye along the pixel's ray.
void addTrails(ivec2 p, uvec2 trail, inout float sums[kSplatChannels]) {
  float depth = float(trail.x);
  vec2 ndc = (vec2(p) + 0.5) / vec2(uSize) * 2.0 - 1.0;
  vec4 far = view.inverseViewProjection * vec4(ndc, 1.0, 1.0);
  vec3 toEye = normalize(view.eye.xyz - far.xyz / far.w);
  sums[0] += depth;
  sums[1] += float(trail.y);
  sums[2] += depth;
  sums[3] += depth * toEye.x;
  sums[4] += depth * toEye.y;
  sums[5] += depth * toEye.z;
}

// Adds a coarser level's sums at view pixel p, interpolated bilinearly
// between the centres of its pixels (clamped at the level's edges).
void addLevel(int level, ivec2 p, inout float sums[kSplatChannels]) {
  ivec2 size = splatLevelSize(uSize, level);
  vec2 at = (vec2(p) + 0.5) / float(1 << level) - 0.5;
  ivec2 i0 = ivec2(floor(at));
  vec2 f = at - vec2(i0);
  // Nothing to read where no splat of this level touched the taps' tiles.
  ivec2 t0 = clamp(i0, ivec2(0), size - 1) / kSplatTile, t1 = clamp(i0 + 1, ivec2(0), size - 1) / kSplatTile;
  uint first = splatTileOffset(uSize, level), across = uint(splatLevelTiles(uSize, level).x);
  bool marked = false;
  for (int ty = t0.y; ty <= t1.y; ++ty)
    for (int tx = t0.x; tx <= t1.x; ++tx) marked = marked || occupied[first + uint(ty) * across + uint(tx)] != 0u;
  if (!marked) return;
  uint offset = splatLevelOffset(uSize, level);
  for (int dy = 0; dy <= 1; ++dy)
    for (int dx = 0; dx <= 1; ++dx) {
      float w = (dx == 0 ? 1.0 - f.x : f.x) * (dy == 0 ? 1.0 - f.y : f.y);
      if (w == 0.0) continue;
      ivec2 q = clamp(i0 + ivec2(dx, dy), ivec2(0), size - 1);
      addSums(offset + uint(q.y) * uint(size.x) + uint(q.x), w, sums);
    }
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= uSize.x || p.y >= uSize.y) return;
  float sums[kSplatChannels] = float[](0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
  uint index = uint(p.y) * uint(uSize.x) + uint(p.x);
  // Each splat adds at least 8 to channel 2, each trail pixel to channel 6:
  // zero in both means nothing was drawn here, and the sums need no zeroing.
  uvec4 first = accum[index * 2u], second = accum[index * 2u + 1u];
  if (first.z != 0u || second.z != 0u) {
    addSums(first, second, 1.0, sums);
    if (second.z != 0u) addTrails(p, second.zw, sums);
    accum[index * 2u] = uvec4(0u);
    accum[index * 2u + 1u] = uvec4(0u);
  }
  for (int level = 1; level < uSplatLevels; ++level) addLevel(level, p, sums);
  vec4 color, normal;
  float light;
  resolveSplat(sums, color, normal, light);
  imageStore(uColor, p, color);
  imageStore(uNormal, p, normal);
  imageStore(uLight, p, vec4(light));
}
