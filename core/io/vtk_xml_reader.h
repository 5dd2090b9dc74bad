// readVtkXml(): a VTK XML file of one dataset (.vti image data, .vtr
// rectilinear grid, .vts structured grid, .vtu unstructured grid, .vtp
// polydata) read by VTK's own XML readers, after checkVtkXml has held every
// array's payload against its counts and the memory budget.
//
// A structured reader first reads only the XML structure (UpdateInformation):
// the whole extent must be non-empty and its point count within
// VectorField::kMaxPoints and the memory budget before any array is read. An
// unstructured grid's or polydata's cells are checked once read
// (checkVtkCells). Any error VTK reports while
// reading (bad XML, short or undecodable data) becomes an Error naming the file.
#pragma once

#include <filesystem>

#include <vtkSmartPointer.h>

#include "core/io/field_format.h"
#include "core/io/load_options.h"

class vtkDataSet;

namespace sandstorm {

vtkSmartPointer<vtkDataSet> readVtkXml(const std::filesystem::path& path, FieldFormat format,
                                       const LoadOptions& options);

}  // namespace sandstorm
