// readVtkLegacy(): a legacy VTK file (.vtk, ASCII or BINARY) holding
// STRUCTURED_POINTS, RECTILINEAR_GRID, STRUCTURED_GRID, UNSTRUCTURED_GRID or
// POLYDATA, parsed and checked
// whole by Sandstorm's own parser (vtk_legacy_parser.h: VTK's legacy readers
// crash on some malformed files) and handed on as the VTK dataset the rest of
// the loader works with: the file's VECTORS are its active vectors, point and
// cell arrays keep their names.
#pragma once

#include <filesystem>

#include <vtkSmartPointer.h>

#include "core/io/load_options.h"

class vtkDataSet;

namespace sandstorm {

vtkSmartPointer<vtkDataSet> readVtkLegacy(const std::filesystem::path& path,
                                          const LoadOptions& options);

}  // namespace sandstorm
