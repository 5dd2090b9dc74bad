// readVtkLegacy(): a legacy VTK file (.vtk, ASCII or BINARY) holding
// STRUCTURED_POINTS, RECTILINEAR_GRID or STRUCTURED_GRID, read by VTK's own
// readers.
//
// Before VTK sees the file, its header is checked here: the dataset type, the
// DIMENSIONS (positive, their product within VectorField::kMaxPoints and the
// memory budget), SPACING > 0, and every POINTS / *_COORDINATES / POINT_DATA
// count against the dimensions and the file's size, so a damaged header gives
// an Error naming the line instead of a huge allocation. Afterwards any error
// VTK reported (including its warnings about short data) becomes an Error.
#pragma once

#include <filesystem>

#include <vtkSmartPointer.h>

#include "core/io/load_options.h"

class vtkDataSet;

namespace sandstorm {

vtkSmartPointer<vtkDataSet> readVtkLegacy(const std::filesystem::path& path,
                                          const LoadOptions& options);

}  // namespace sandstorm
