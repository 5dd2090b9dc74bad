// Grids sampled onto other grids, trilinearly (VectorField::sample):
//   resampleField(): onto a bounds-preserving grid of `dims` points, for
//     formats that have no library of their own to resample with (FGA, VF).
//     Throws Error for non-positive dims.
//   resampleOnto(): a series' step onto its first step's grid (a moving or
//     growing mesh's step, a step at another resolution), since playback
//     blends neighbouring steps point by point. A point of `grid` outside
//     the step's bounds, or whose cell in the step has a corner outside the
//     field, is marked outside (particles there follow sim.boundary); the
//     step's scalar arrays are sampled alike; the result is halves where
//     `grid` is (the series' field.precision).
#pragma once

#include "core/field/vector_field.h"

namespace sandstorm {

VectorField resampleField(const VectorField& field, const glm::ivec3& dims);

VectorField resampleOnto(const VectorField& step, const VectorField& grid);

}  // namespace sandstorm
