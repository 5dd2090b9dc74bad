#version 450 core
// OpacityShadowMap, step 2: one invocation turns the particles' extent in the
// light's frame into the shadow block (shadow_block.glsl): square cells no
// smaller than a particle (so a particle's light-blocking lands in a cell or
// two, not scattered dots), a cell of margin on each side (the receivers'
// bilinear filter reaches half a cell beyond the particles), the layers
// spanning the extent plus a particle's radius. Resets
// the extent for the next frame.
#include "ordered_bits.glsl"

layout(local_size_x = 1) in;
layout(std430, binding = 14) restrict buffer Bounds { uint least[3]; uint greatest[3]; } bounds;
layout(std140, binding = 15) writeonly restrict buffer Block {
  vec4 right, up, toLight, corner, params;
} block;
layout(location = 2) uniform vec3 uRight;
layout(location = 3) uniform vec3 uUp;
layout(location = 4) uniform vec3 uToLight;
layout(location = 5) uniform float uSize;      // the particles' diameter (m)
layout(location = 6) uniform float uDensity;   // render.shadow_density
layout(location = 7) uniform int uResolution;  // the texture's side
layout(location = 8) uniform int uLayers;
layout(location = 9) uniform int uEnabled;

void main() {
  bool any = bounds.least[0] <= bounds.greatest[0];
  vec3 lo = vec3(fromOrdered(bounds.least[0]), fromOrdered(bounds.least[1]), fromOrdered(bounds.least[2]));
  vec3 hi = vec3(fromOrdered(bounds.greatest[0]), fromOrdered(bounds.greatest[1]), fromOrdered(bounds.greatest[2]));
  for (int a = 0; a < 3; ++a) {
    bounds.least[a] = 0xffffffffu;
    bounds.greatest[a] = 0u;
  }
  bool on = uEnabled != 0 && any;
  vec2 extent = hi.xy - lo.xy;
  float cell = max(uSize, max(extent.x, extent.y) / float(uResolution - 4));
  vec2 cells = ceil(extent / cell) + 2.0;
  float radius = 0.5 * uSize;
  float top = hi.z + radius, span = max(hi.z - lo.z + uSize, 1e-6);
  block.right = vec4(uRight, on ? 1.0 : 0.0);
  block.up = vec4(uUp, 1.0 / cell);
  block.toLight = vec4(uToLight, float(uLayers));
  block.corner = vec4(lo.xy - cell, top, 1.0 / span);
  block.params = vec4(uDensity / (cell * cell), float(uResolution), cells);
}
