// GradientNoise (core/field/gradient_noise.h) in GLSL: the analytic fields'
// noise (field_equation.glsl) and the flow solver's forced eddies
// (fluid_cells.comp). Same hash, lattice gradients and quintic fade as the CPU's.
uint noiseHash(uint x) {  // lowbias32, as GradientNoise's hash
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

const vec3 kNoiseDirections[12] = vec3[](vec3(1, 1, 0), vec3(-1, 1, 0), vec3(1, -1, 0), vec3(-1, -1, 0),
                                         vec3(1, 0, 1), vec3(-1, 0, 1), vec3(1, 0, -1), vec3(-1, 0, -1),
                                         vec3(0, 1, 1), vec3(0, -1, 1), vec3(0, 1, -1), vec3(0, -1, -1));

vec3 latticeGradient(uint seed, ivec3 c) {
  uint h = noiseHash(seed ^ noiseHash(uint(c.x) ^ noiseHash(uint(c.y) ^ noiseHash(uint(c.z)))));
  return kNoiseDirections[h % 12u];
}

// (d/dx, d/dy, d/dz, value) of GradientNoise(seed) at p.
vec4 noiseValueAndGradient(uint seed, vec3 p) {
  vec3 cellf = floor(p);
  ivec3 cell = ivec3(cellf);
  vec3 f = p - cellf;
  vec3 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  vec3 du = 30.0 * f * f * (f * (f - 2.0) + 1.0);
  float value = 0.0;
  vec3 grad = vec3(0.0);
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int c = 0; c < 2; ++c) {
        vec3 g = latticeGradient(seed, cell + ivec3(a, b, c));
        float n = dot(g, f - vec3(a, b, c));
        float wx = a != 0 ? u.x : 1.0 - u.x, wy = b != 0 ? u.y : 1.0 - u.y, wz = c != 0 ? u.z : 1.0 - u.z;
        float dwx = a != 0 ? du.x : -du.x, dwy = b != 0 ? du.y : -du.y, dwz = c != 0 ? du.z : -du.z;
        float w = wx * wy * wz;
        value += w * n;
        grad += w * g + n * vec3(dwx * wy * wz, wx * dwy * wz, wx * wy * dwz);
      }
  return vec4(grad, value);
}
