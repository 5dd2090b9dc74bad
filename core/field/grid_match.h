// Whether a series' step lies on its first step's grid, and if not, how it
// differs, in words for the step's error: every step of a series must share
// the first's points per axis and bounds (playback blends neighbouring steps
// point by point, and the walls' textures keep their size).
#pragma once

#include <string>

#include "core/field/vector_field.h"

namespace sandstorm {

// "" when `step` has `first`'s dims and bounds; otherwise, e.g., "a 9x8x8
// grid, not the first step's 8x8x8" or "bounds [0,0,0]..[2,1,1] m, not the
// first step's [0,0,0]..[1,1,1] m".
std::string gridDifference(const VectorField& step, const VectorField& first);

}  // namespace sandstorm
