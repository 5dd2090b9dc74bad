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
// Trails (trail_common.glsl) add two sums of their own to a full-resolution
// pixel's spare channels: 6 sum of -ln(1 - alpha), 7 the same times t. A
// trail's weight is its optical depth (as with SHADOWS), its light 1 and its
// normal towards the eye along the pixel's ray, so the resolve adds channel 6
// to channels 0 and 2 and to the normal sums: two atomics a trail pixel,
// not six.
const uint kSplatTrailChannel = 6u;
const uint kSplatTrailChannels = 2u;
const float kSplatScale = 4096.0;
// Motion blur by a filter (MOTION_FILTER: render.shutter with render.blur =
// filter): each splat also adds its motion m over the shutter (view pixels)
// to every tile of its level's grid it is listed in (the tiled pass's
// 32-pixel tiles), as five integer sums a tile (kSplatMotionStride ints,
// indexed like the tiles: splatTileOffset): its weight w (its opacity in
// 16ths), w m and w times m's axis with the angle doubled, (mx^2 - my^2,
// 2 mx my) / |m|, in half pixels. Axes along one line add up whichever way
// the paths run (a vortex's front and back cross a pixel in opposite
// directions: their motions cancel, their axes do not). Once a splat and
// tile, not once a pixel: motion changes slowly across the image, and a
// sum a pixel cost the splat pass half its time again. Integers, so the sum
// does not depend on the order splats come in; a tile of more than 2^20
// splats adds them shifted right (splatMotionShift) to stay within an int.
// ParticleMotionFilter interpolates the tiles' means between their centres.
const uint kSplatMotionStride = 8u;

// The tiled pass: tiles of kSplatTile x kSplatTile pixels, at most
// kSplatMaxTiles a view (a 4K view has 8160; a histogram of them fits in a
// workgroup's shared memory); each tile's list is cut into chunks (of 8192
// records unless SANDSTORM_SPLAT_CHUNK says), one workgroup a chunk, so dense
// tiles spread over many workgroups; at most kSplatMaxBinGroups workgroups
// bin a view's particles.
const int kSplatTile = 32;
const uint kSplatMaxTiles = 8192u;
const uint kSplatMaxBinGroups = 1024u;
// Levels (render.splat_detail): a splat wider than the detail is drawn on a
// coarser grid instead, level L's pixels 2^L view pixels wide (up to
// kSplatLevels levels), so it covers at most about detail^2 pixels whatever
// its size; the resolve adds each level's sums, bilinearly upsampled, to the
// full-resolution ones (the sums are linear, so this is the same image
// function sampled more coarsely). The levels' sums follow one another in
// the buffer, and so do their tiles in the tiled pass's histogram.
const int kSplatLevels = 4;

ivec2 splatLevelSize(ivec2 size, int level) { return (size + (1 << level) - 1) >> level; }

// The first pixel of a level's sums in the buffer.
uint splatLevelOffset(ivec2 size, int level) {
  uint offset = 0u;
  for (int l = 0; l < level; ++l) {
    ivec2 s = splatLevelSize(size, l);
    offset += uint(s.x) * uint(s.y);
  }
  return offset;
}

ivec2 splatLevelTiles(ivec2 size, int level) { return (splatLevelSize(size, level) + kSplatTile - 1) / kSplatTile; }

// The first of a level's tiles; splatTileOffset(size, levels) is their number.
uint splatTileOffset(ivec2 size, int level) {
  uint offset = 0u;
  for (int l = 0; l < level; ++l) {
    ivec2 t = splatLevelTiles(size, l);
    offset += uint(t.x) * uint(t.y);
  }
  return offset;
}

// The right shift of a tile's motion integers for a tile of `splats` records.
int splatMotionShift(uint splats) {
  int shift = 0;
  while (shift < 20 && (splats >> uint(shift)) > (1u << 20)) ++shift;
  return shift;
}
