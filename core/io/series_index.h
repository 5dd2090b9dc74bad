// indexSeries(): a field file's steps, found without reading them: a .pvd's
// times and files, or the time steps a file holds itself (Exodus, EnSight,
// OpenFOAM, NetCDF, CGNS); a file of one field is a series of one step. Only
// the first step is read (it fixes the grid and is what the start shows), so a
// series of any length opens in the time one step takes. SeriesReader reads
// the others as playback needs them.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "core/field/vector_field.h"
#include "core/io/load_options.h"
#include "core/io/series_reader.h"

namespace sandstorm {

struct SeriesIndex {
  std::vector<double> times;                  // increasing
  std::vector<SeriesReader::Source> sources;  // one a time
  std::shared_ptr<const VectorField> first;   // step 0, read
  LoadOptions stepOptions;                    // how every later step is read
};

// Throws Error naming the file (a step's time not increasing, the first step unreadable).
// `report` gets the first step's LoadReport, its times every step's.
SeriesIndex indexSeries(const std::filesystem::path& path, const LoadOptions& options,
                        LoadReport* report = nullptr);

}  // namespace sandstorm
