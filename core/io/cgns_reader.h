// readCgns(): a CGNS file (.cgns, HDF5 or the older ADF inside) read by VTK's vtkCGNSReader at
// options.timeStep: the first base's zones, structured or unstructured
// (merged by the field extractor), their flow solutions at the vertices or
// cell centres (VelocityX/Y/Z joined into a vector), the base's iterative
// data as time steps (report.times).
//
// Before the reader runs, the file is asked through the CGNS library (which
// reads its node tree, not the data): zone sizes and every unstructured
// section within the memory budget, each section's element type one VTK
// reads (not the polyhedral NGON_n/NFACE_n), and its connectivity, read,
// naming the zone's vertices. Throws Error naming the file, the zone and what
// was wrong.
#pragma once

#include <filesystem>

#include <vtkSmartPointer.h>

#include "core/io/load_options.h"

class vtkDataObject;

namespace sandstorm {

vtkSmartPointer<vtkDataObject> readCgns(const std::filesystem::path& path,
                                        const LoadOptions& options, LoadReport& report);

}  // namespace sandstorm
