#version 450 core
// FieldPairBlend: a time-varying field's pair blended point by point into one
// grid once a frame, so that the update samples one grid instead of two
// (a 256^3 pair of halves is twice what the L2 cache must serve). Point i is
// a + (b - a) * w (each component, `precise`: no fused multiply-add, as the
// CPU twin computes it), valid where both are; with FIELD_BUFFER_HALF it is
// rounded to the nearest half (ties to even, with integer operations:
// GLSL's packHalf2x16 leaves the rounding to the implementation), the twin of
// nearestHalf in core/util/half_float.h. The layouts are GpuField's: a vec4
// a point (xyz, valid), or four halves (x, y | z, valid).

layout(local_size_x = 256) in;

#ifdef FIELD_BUFFER_HALF
layout(std430, binding = 14) readonly restrict buffer PairFirst { uvec2 first[]; };
layout(std430, binding = 15) readonly restrict buffer PairSecond { uvec2 second[]; };
layout(std430, binding = 13) writeonly restrict buffer Blended { uvec2 blended[]; };
#else
layout(std430, binding = 14) readonly restrict buffer PairFirst { vec4 first[]; };
layout(std430, binding = 15) readonly restrict buffer PairSecond { vec4 second[]; };
layout(std430, binding = 13) writeonly restrict buffer Blended { vec4 blended[]; };
#endif

layout(location = 0) uniform float uWeight;  // towards the second
layout(location = 1) uniform uint uPoints;

#ifdef FIELD_BUFFER_HALF
// The bits of the half nearest to x, |x| <= 65504 (halfBits in half_float.h).
uint nearestHalfBits(float x) {
  uint bits = floatBitsToUint(x);
  uint sign = bits & 0x80000000u;
  uint magnitude = bits ^ sign;
  if (magnitude < 0x38800000u) {
    // Below 2^-14 halves are 2^-24 apart: adding 0.5 rounds to that grid
    // (ties to even) and subtracting it is exact; then a count of 2^-24.
    precise float up = uintBitsToFloat(magnitude) + 0.5;
    precise float back = up - 0.5;
    return (sign >> 16u) | uint(back * 16777216.0);
  }
  uint rounded = (magnitude + 0x0fffu + ((magnitude >> 13u) & 1u)) & ~0x1fffu;
  return (sign >> 16u) | ((rounded - 0x38000000u) >> 13u);
}
#endif

void main() {
  uint stride = gl_NumWorkGroups.x * 256u;
  for (uint i = gl_GlobalInvocationID.x; i < uPoints; i += stride) {
#ifdef FIELD_BUFFER_HALF
    uvec2 ha = first[i], hb = second[i];
    vec2 axy = unpackHalf2x16(ha.x), azw = unpackHalf2x16(ha.y);
    vec2 bxy = unpackHalf2x16(hb.x), bzw = unpackHalf2x16(hb.y);
    precise vec3 c = vec3(axy, azw.x) + (vec3(bxy, bzw.x) - vec3(axy, azw.x)) * uWeight;
    bool valid = azw.y != 0.0 && bzw.y != 0.0;
    blended[i] = uvec2(nearestHalfBits(c.x) | (nearestHalfBits(c.y) << 16u),
                       nearestHalfBits(c.z) | (valid ? 0x3c000000u : 0u));
#else
    vec4 a = first[i], b = second[i];
    precise vec3 c = a.xyz + (b.xyz - a.xyz) * uWeight;
    blended[i] = vec4(c, a.w != 0.0 && b.w != 0.0 ? 1.0 : 0.0);
#endif
  }
}
