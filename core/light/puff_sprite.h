// The soft puff every billboard and splat is textured with (ParticleRender's
// sprite): a smooth radial falloff with a little lumpiness, so overlapping
// particles read as a cloud rather than as discs. Pure data, so the renderers
// and the light model (its mean coverage) agree on one definition.
#pragma once

#include <cstdint>
#include <vector>

namespace sandstorm {

// kPuffSize x kPuffSize coverage values (0..255), rows from v = -1 to 1.
inline constexpr int kPuffSize = 64;
std::vector<std::uint8_t> puffSpritePixels();

// The sprite's mean coverage over the unit disc the billboard shows (0..1):
// how much of a particle's disc blocks light, on average, at full opacity.
float puffCoverage();

}  // namespace sandstorm
