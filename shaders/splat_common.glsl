// ParticleSplat's accumulation buffer: kSplatStride uints per pixel (32
// bytes, one memory sector), kSplatChannels of them used, fixed point with
// kSplatScale steps per unit, added to with atomicAdd (integer addition is
// associative, so the sums do not depend on the order particles arrive in, and
// signed values add as two's complement):
//   0 sum of alpha,  1 sum of alpha * age,  2 sum of -ln(1 - alpha),
//   3-5 sum of alpha * normal (signed).
// Colour is linear in age (mix of the birth and death colours), so alpha * age
// carries the colour sums in one channel instead of three.
const uint kSplatStride = 8u;
const uint kSplatChannels = 6u;
const float kSplatScale = 4096.0;

layout(std430, binding = 6) coherent restrict buffer SplatAccumulation { uint accum[]; };
