// extractVectorField(): the chosen vector array of a VTK dataset (image data,
// rectilinear or structured grid) as a dense VectorField.
//
// The array is options.arrayName, or the point data's active vectors, or its
// only 3-component array. An array found only in cell data is moved to the
// points by vtkCellDataToPointData. Missing, ambiguous or non-vector arrays
// throw Error listing the arrays present (and their component counts).
//
// Image data is copied point for point (spacing must be > 0, the direction
// axis-aligned). Other grids, and image data when options.resolution asks for
// another resolution, are resampled by vtkResampleToImage over the data's
// bounding box; points outside a curvilinear grid's cells get zero. NaN and
// Inf vectors become zero, counted in report.nonFinite and logged.
#pragma once

#include <filesystem>

#include "core/field/vector_field.h"
#include "core/io/load_options.h"

class vtkDataSet;

namespace sandstorm {

VectorField extractVectorField(vtkDataSet* data, const std::filesystem::path& path,
                               const LoadOptions& options, LoadReport& report);

}  // namespace sandstorm
