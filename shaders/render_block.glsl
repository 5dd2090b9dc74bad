// How particles look: the twin of RenderBlock in contexts/render/frame_blocks.h.
const int kColorSamples = 91;  // ColorMap::kGpuSamples
layout(std140, binding = 2) uniform RenderBlock {
  vec4 colorBirth;      // rgb, a: opacity at birth
  vec4 colorDeath;      // rgb, a: opacity at death
  vec4 lightDirection;  // xyz towards the light (unit), w: ambient share
  vec4 params;          // x: size (m), y: softness (m), z: 1 for billboards, 0 for points, w: shutter (s)
  vec4 colorScale;      // x: quantity (ColorQuantity), y: value at t = 0, z: at t = 1, w: 1 log scale
  vec4 colorTable[kColorSamples];  // the colour map's rgb at t = i / (kColorSamples - 1)
  // The colour grids' place (units 5 and 6), as the particles' field's.
  vec4 fieldMin;
  vec4 fieldIndexScale;
  ivec4 fieldDims;
  vec4 placementOffset;  // xyz, w: scale
  vec4 placementRotation[3];
  vec4 colorGrid;  // x: blend, y: 1 with a next frame, z: factor, w: 1 with a grid
  vec4 light;      // rgb: the direct light's colour times its strength, w: 1 with shadows
  vec4 haze;       // x: render.scattering (1/m)
  vec4 splat;      // x: render.splat_detail (px; 0: every splat at full resolution),
                   // y: render.splat_overlap (0: off)
} look;

layout(binding = 5) uniform sampler3D uColorGrid;      // R: |curl| (VectorField x)
layout(binding = 6) uniform sampler3D uColorGridNext;  // a time-varying field's next frame

// The colour grid's value the particles feel at x (vorticity or a file's
// scalar array, core/color/color_grid.h): VectorField::sample of the grid at
// the placement's local point (as fieldCell() and trilinear() in
// particle_physics.glsl), blended, times the factor (|strength| for
// vorticity, 1 for an array).
float colorGridSample(sampler3D grid, ivec3 i0, ivec3 i1, vec3 f) {
  float c000 = texelFetch(grid, ivec3(i0.x, i0.y, i0.z), 0).x, c100 = texelFetch(grid, ivec3(i1.x, i0.y, i0.z), 0).x;
  float c010 = texelFetch(grid, ivec3(i0.x, i1.y, i0.z), 0).x, c110 = texelFetch(grid, ivec3(i1.x, i1.y, i0.z), 0).x;
  float c001 = texelFetch(grid, ivec3(i0.x, i0.y, i1.z), 0).x, c101 = texelFetch(grid, ivec3(i1.x, i0.y, i1.z), 0).x;
  float c011 = texelFetch(grid, ivec3(i0.x, i1.y, i1.z), 0).x, c111 = texelFetch(grid, ivec3(i1.x, i1.y, i1.z), 0).x;
  float c00 = c000 + (c100 - c000) * f.x, c10 = c010 + (c110 - c010) * f.x;
  float c01 = c001 + (c101 - c001) * f.x, c11 = c011 + (c111 - c011) * f.x;
  float c0 = c00 + (c10 - c00) * f.y, c1 = c01 + (c11 - c01) * f.y;
  return c0 + (c1 - c0) * f.z;
}

float colorGridAt(vec3 x) {
  if (look.colorGrid.w == 0.0) return 0.0;
  mat3 rotation = mat3(look.placementRotation[0].xyz, look.placementRotation[1].xyz, look.placementRotation[2].xyz);
  vec3 local = (transpose(rotation) * (x - look.placementOffset.xyz)) * (1.0 / look.placementOffset.w);
  ivec3 dims = look.fieldDims.xyz;
  vec3 u = clamp((local - look.fieldMin.xyz) * look.fieldIndexScale.xyz, vec3(0.0), vec3(dims - 1));
  ivec3 i0 = min(ivec3(floor(u)), max(dims - 2, ivec3(0)));
  ivec3 i1 = min(i0 + 1, dims - 1);
  vec3 f = u - vec3(i0);
  float w = colorGridSample(uColorGrid, i0, i1, f);
  if (look.colorGrid.y != 0.0) w = w + (colorGridSample(uColorGridNext, i0, i1, f) - w) * look.colorGrid.x;
  return look.colorGrid.z * w;
}

// The colour quantity's value for a particle at `position` (colorValue in
// core/color/color_scale.h).
float colorValue(float age, vec3 velocity, vec3 position) {
  int quantity = int(look.colorScale.x);
  return quantity == 0   ? age
         : quantity == 1 ? length(velocity)
         : quantity >= 5 ? colorGridAt(position)
                         : velocity[clamp(quantity - 2, 0, 2)];
}

// The colour map's coordinate for a particle at `position`: ColorScale::coordinate
// of colorValue, in the same operations.
float colorCoordinate(float age, vec3 velocity, vec3 position) {
  float v = colorValue(age, velocity, position);
  float lo = look.colorScale.y, hi = look.colorScale.z;
  if (look.colorScale.w > 0.5) {
    v = log(max(v, lo));
    lo = log(lo);
    hi = log(hi);
  }
  return hi > lo ? clamp((v - lo) / (hi - lo), 0.0, 1.0) : 0.5;
}

// The colour map at t, interpolating its samples (ColorMap::lookupTable).
vec3 colorAt(float t) {
  float x = clamp(t, 0.0, 1.0) * float(kColorSamples - 1);
  int i = min(int(x), kColorSamples - 2);
  return mix(look.colorTable[i].rgb, look.colorTable[i + 1].rgb, x - float(i));
}
