// ParticleSplat's per-pixel sums: kSplatChannels uints, fixed point with
// kSplatScale steps per unit, added to with atomicAdd (integer addition is
// associative, so the sums do not depend on the order particles arrive in, and
// signed values add as two's complement):
//   0 sum of alpha,  1 sum of alpha * t (the colour map's coordinate),
//   2 sum of -ln(1 - alpha),  3-5 sum of alpha * normal (signed),
// With SHADOWS (render.shadows) the weights are w = -ln(1 - alpha), whose
// sum channel 2 holds already, which frees channel 0 for the sum of w times
// the light reaching the particle: the same six channels (a seventh made
// every splat view 1.3-1.6 times slower on an H100).
// One channel for colour, not three: the resolve maps the mean t, exact for
// the life map (linear in t) and close for the others.
// The atomic pass keeps them in a buffer, kSplatStride uints (32 bytes, one
// memory sector) a pixel; the tiled pass in shared memory, a tile at a time.
const uint kSplatStride = 8u;
const uint kSplatChannels = 6u;
const float kSplatScale = 4096.0;
// The tiled pass: tiles of kSplatTile x kSplatTile pixels, at most
// kSplatMaxTiles a view (a 4K view has 8160; a histogram of them fits in a
// workgroup's shared memory); each tile's list is cut into chunks (of 8192
// records unless SANDSTORM_SPLAT_CHUNK says), one workgroup a chunk, so dense
// tiles spread over many workgroups; at most kSplatMaxBinGroups workgroups
// bin a view's particles.
const int kSplatTile = 32;
const uint kSplatMaxTiles = 8192u;
const uint kSplatMaxBinGroups = 1024u;
