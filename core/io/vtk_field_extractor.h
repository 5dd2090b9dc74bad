// extractVectorField(): the chosen vector array of a VTK data object (image
// data, rectilinear, structured or unstructured grid, polydata, or a
// multiblock of any of them) as a dense VectorField.
//
// The array is chosen over every block (vector_array_choice.h: by name, the
// active vectors, the only vector array, or three components joined), cell
// data moved to the points. Blocks without it are left out and named in the
// report.
//
// One image block is copied point for point (spacing must be > 0, the
// direction axis-aligned) unless options.resolution asks for another grid.
// Anything else is resampled (mesh_resampler.h) over the blocks' bounding box:
// a structured block at its own dimensions, a mesh at the resolution its
// cells suggest (sampling_grid.h), or options.resolution; points outside
// every cell are marked invalid (the validity mask). NaN and Inf vectors
// become zero, counted in report.nonFinite and logged.
#pragma once

#include <filesystem>

#include "core/field/vector_field.h"
#include "core/io/load_options.h"

class vtkDataObject;

namespace sandstorm {

VectorField extractVectorField(vtkDataObject* data, const std::filesystem::path& path,
                               const LoadOptions& options, LoadReport& report);

}  // namespace sandstorm
