#include "core/io/series_index.h"

#include "core/io/field_format.h"
#include "core/io/field_loader.h"
#include "core/io/precision_choice.h"
#include "core/io/pvd_file.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

// A mesh's steps sampled straight onto the first step's grid, its points and
// its box, even where a later step's cells move or grow: one interpolation,
// not one onto the step's own grid and another onto the first's
// (SeriesReader resamples a step whose grid still differs, such as an image's).
void pinMeshSteps(SeriesIndex& index, const LoadReport& first) {
  if (!first.resampled) return;
  index.stepOptions.resolution = index.first->dims();
  index.stepOptions.samplingBox = index.first->bounds();
}

}  // namespace

SeriesIndex indexSeries(const std::filesystem::path& path, const LoadOptions& options,
                        LoadReport* report) {
  LoadReport local;
  LoadReport& first = report ? *report : local;
  SeriesIndex index;
  index.stepOptions = options;
  if (detectFieldFormat(path) == FieldFormat::VtkCollection) {
    // readPvd sorts by time, groups a time's parts and refuses repeated times.
    for (const PvdFrame& f : readPvd(path)) {
      index.times.push_back(f.time);
      index.sources.push_back({f.file(), 0, f.parts});
    }
    first = LoadReport{};
    VectorField field = loadFieldParts(index.sources.front().parts, path, options, &first);
    if (chooseHalf(field, index.times.size() > 1 ? kSeriesGrids : 1, options, first))
      index.stepOptions.halfPrecision = true;
    index.first = std::make_shared<const VectorField>(std::move(field));
    first.times = index.times;
    pinMeshSteps(index, first);
    return index;
  }
  VectorField field = loadField(path, options, &first);
  if (chooseHalf(field, first.times.size() > 1 ? kSeriesGrids : 1, options, first))
    index.stepOptions.halfPrecision = true;
  index.first = std::make_shared<const VectorField>(std::move(field));
  if (first.times.size() <= 1) {
    index.times = {first.times.empty() ? 0.0 : first.times.front()};
    index.sources = {{path, 0}};
    return index;
  }
  for (std::size_t i = 0; i < first.times.size(); ++i) {
    if (i > 0 && !(first.times[i] > first.times[i - 1]))
      throw Error(concat(path.string(), ": time step ", i, " (t = ", first.times[i],
                         ") does not come after step ", i - 1, " (t = ", first.times[i - 1], ")"));
    index.times.push_back(first.times[i]);
    index.sources.push_back({path, i});
  }
  // Every step on the grid the first one chose (a mesh's steps resample onto it).
  index.stepOptions.resolution = index.first->dims();
  pinMeshSteps(index, first);
  return index;
}

}  // namespace sandstorm
