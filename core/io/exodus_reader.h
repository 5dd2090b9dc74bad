// readExodus(): an Exodus II mesh (.e .exo .g .ex2: finite-element output,
// NetCDF inside) read by VTK's vtkExodusIIReader at options.timeStep: every
// element block (merged by the field extractor), every nodal and element
// variable (vel_x, vel_y, vel_z joined into "vel" by the reader, or by
// --array), its time steps in report.times.
//
// Before the reader runs, readNetcdfHeader() checks that every variable lies
// within the file, and the mesh is held to the memory budget: the nodes'
// coordinates, every block's connectivity and one step of the nodal
// variables. Throws Error naming the file and what was wrong.
#pragma once

#include <filesystem>

#include <vtkSmartPointer.h>

#include "core/io/load_options.h"

class vtkDataObject;

namespace sandstorm {

vtkSmartPointer<vtkDataObject> readExodus(const std::filesystem::path& path,
                                          const LoadOptions& options, LoadReport& report);

}  // namespace sandstorm
