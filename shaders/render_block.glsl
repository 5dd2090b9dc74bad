// How particles look: the twin of RenderBlock in contexts/render/frame_blocks.h.
const int kColorSamples = 91;  // ColorMap::kGpuSamples
layout(std140, binding = 2) uniform RenderBlock {
  vec4 colorBirth;      // rgb, a: opacity at birth
  vec4 colorDeath;      // rgb, a: opacity at death
  vec4 lightDirection;  // xyz towards the light (unit), w: ambient share
  vec4 params;          // x: size (m), y: softness (m), z: 1 for billboards, 0 for points
  vec4 colorScale;      // x: quantity (ColorQuantity), y: value at t = 0, z: at t = 1, w: 1 log scale
  vec4 colorTable[kColorSamples];  // the colour map's rgb at t = i / (kColorSamples - 1)
} look;

// The colour map's coordinate for a particle: ColorScale::coordinate of
// colorValue (core/color/color_scale.h), in the same operations.
float colorCoordinate(float age, vec3 velocity) {
  int quantity = int(look.colorScale.x);
  float v = quantity == 0 ? age : quantity == 1 ? length(velocity) : velocity[clamp(quantity - 2, 0, 2)];
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
