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
// frame, every part of it; FieldSequence reads them all), OpenVDB (.vdb), Unreal (.fga) and
// Unity (.vf). See load_options.h for axes, resampling and the memory budget.
// Every failure throws sandstorm::Error whose message starts with the file
// name and says what was expected.
#pragma once

#include <filesystem>
#include <vector>

#include "core/field/vector_field.h"
#include "core/io/load_options.h"

namespace sandstorm {

VectorField loadField(const std::filesystem::path& path, const LoadOptions& options = {},
                      LoadReport* report = nullptr);

// One dataset stored as several files: a .pvd's parts at one time (ParaView
// writes a part a rank of a parallel run, or a block of a multiblock). Each
// part is read by its VTK format's reader with the checks loadField makes,
// then every part's datasets are taken together as the blocks of one
// multiblock, as a .vtm's are: the vectors chosen over every block and
// resampled onto one grid (not one part shown as if it were the whole).
// Each part is checked against field.memory_budget before VTK allocates it,
// and the parts read may take twice the budget together, as a .vtm's blocks
// may (checked as each is read). `dataset` names them in errors and notes
// (the .pvd). One part is loadField's.
VectorField loadFieldParts(const std::vector<std::filesystem::path>& parts,
                           const std::filesystem::path& dataset, const LoadOptions& options = {},
                           LoadReport* report = nullptr);

}  // namespace sandstorm
