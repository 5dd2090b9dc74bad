// loadField(): the one entry point for reading a vector field file.
//
//   LoadOptions options;
//   options.arrayName = "velocity";
//   LoadReport report;
//   VectorField f = loadField("data/tornado.vti", options, &report);
//
// The format is recognised from the content (detectFieldFormat), and a file
// whose extension names another format is refused (checkExtension). Formats:
// legacy VTK (.vtk), VTK XML (.vti, .vtr, .vts), a .pvd time series (its first
// frame; FieldSequence reads them all), OpenVDB (.vdb), Unreal (.fga) and
// Unity (.vf). See load_options.h for axes, resampling and the memory budget.
// Every failure throws sandstorm::Error whose message starts with the file
// name and says what was expected.
#pragma once

#include <filesystem>

#include "core/field/vector_field.h"
#include "core/io/load_options.h"

namespace sandstorm {

VectorField loadField(const std::filesystem::path& path, const LoadOptions& options = {},
                      LoadReport* report = nullptr);

}  // namespace sandstorm
