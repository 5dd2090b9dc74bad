// readEnSight(): an EnSight Gold case (.case; C binary or ascii geometry and
// variables, transient cases too) read by VTK's vtkGenericEnSightReader at
// options.timeStep: every part (merged by the field extractor), every
// per-node and per-element variable, the time set's values as time steps
// (report.times). The case and the step's files are checked first
// (ensight_check.h). Throws Error naming the file and what was wrong.
#pragma once

#include <filesystem>

#include <vtkSmartPointer.h>

#include "core/io/load_options.h"

class vtkDataObject;

namespace sandstorm {

vtkSmartPointer<vtkDataObject> readEnSight(const std::filesystem::path& path,
                                           const LoadOptions& options, LoadReport& report);

}  // namespace sandstorm
