// ParticleSplat's accumulation buffer: kSplatChannels uints per pixel, fixed
// point with kSplatScale steps per unit, added to with atomicAdd (integer
// addition is associative, so the sums do not depend on the order particles
// arrive in, and signed values add as two's complement):
//   0-2 sum of alpha * colour,  3 sum of alpha,  4 sum of -ln(1 - alpha),
//   5-7 sum of alpha * normal (signed).
const uint kSplatChannels = 8u;
const float kSplatScale = 4096.0;

layout(std430, binding = 6) coherent restrict buffer SplatAccumulation { uint accum[]; };
