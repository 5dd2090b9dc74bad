// Counter-based random numbers: the twin of core/sim/counter_rng.h.
// pcg4d (Jarzynski & Olano 2020), integer-only, so every GPU and the CPU agree.

const uint kStreamBirth = 0u;
const uint kStreamBirthBall = 16u;     // 16..31
const uint kStreamVelocityBall = 32u;  // 32..47

uvec4 pcg4d(uvec4 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  v ^= v >> 16u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  return v;
}

// seed = (lo, hi), as Seed in counter_rng.h.
vec4 randomUniform(uvec2 seed, uint frame, uint emitter, uint index, uint stream) {
  uvec4 bits = pcg4d(uvec4(index ^ seed.y, frame, (emitter << 8u) | stream, seed.x));
  return vec4(bits >> 8u) * (1.0 / 16777216.0);
}
