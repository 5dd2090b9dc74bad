// PrecisionChoice: field.precision = "auto" (the default) keeps a field's
// vectors as floats unless they would not fit on the GPU: then as 16-bit
// floats (VectorField::roundToHalf: half the memory and bandwidth, each
// component within 2^-11 of itself), chosen here and said in the load
// report. The rule: the grids a GPU holds at once (one for a steady field;
// kSeriesGrids for a series) at 16 bytes a point, as GpuField keeps a float
// grid (a vec4 in a storage buffer, an RGBA32F texel in a texture), against
// LoadOptions::gpuRoom (the app's share of the smallest GPU).
#pragma once

#include "core/field/vector_field.h"
#include "core/io/field_loader.h"
#include "core/io/load_options.h"

namespace sandstorm {

// The bytes `grids` copies of `field` take on a GPU as floats.
double floatGpuBytes(const VectorField& field, int grids);

// Rounds `field` to halves when options.gpuRoom answers, no precision was
// asked for (options.halfPrecision) and its floats on the GPU would pass it;
// says why in report.notes. A field with a component beyond what halves hold
// stays float (noted too). Returns whether it rounded.
bool chooseHalf(VectorField& field, int grids, const LoadOptions& options, LoadReport& report);

// The grids of a series (or a watched folder) a GPU holds at once: the pair
// being blended, the grid the compute backend blends them into
// (FieldPairBlend), and the step uploaded ahead.
constexpr int kSeriesGrids = 4;

}  // namespace sandstorm
