#include "app/scene_setup.h"

#include <algorithm>
#include <chrono>
#include <future>
#include <thread>

#include "contexts/platform/gpu_memory.h"
#include "core/field/analytic_field_factory.h"
#include "core/field/height_map_io.h"
#include "core/io/budget_advice.h"
#include "core/io/field_format.h"
#include "core/io/field_loader.h"
#include "core/io/precision_choice.h"
#include "core/io/series_index.h"
#include "core/io/vdb_reader.h"
#include "core/sim/main_context.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

// Points along an axis of a sparse grid's dense overview (FieldUpdate::sparse).
constexpr int kSparseOverviewPoints = 64;

// Config paths arrive resolved against their config file; menu choices against `baseDir`.
std::filesystem::path resolve(const std::string& source, const std::filesystem::path& baseDir) {
  const std::filesystem::path p(source);
  return p.is_absolute() || std::filesystem::exists(p) ? p : baseDir / p;
}

// Bytes a step of `field`'s grid takes in memory (vectors, mask, scalar arrays).
double stepBytes(const VectorField& field) {
  double bytes = 12.0 * double(field.pointCount()) + double(field.validity().size());
  for (const VectorField::Scalars& s : field.scalars())
    bytes += 4.0 * double(s.values.size());
  return bytes;
}

// How many steps of `first`'s grid playback may hold (the two being blended
// and those read ahead, within field.memory_budget), and how many threads
// read them: one for each step read ahead, on at most half the cores (the
// walls' threads and the main context keep the rest).
struct StreamPlan {
  std::size_t capacity = 2;
  int readers = 1;
};

StreamPlan streamPlan(const std::filesystem::path& path, const VectorField& first,
                      const FieldSpec& spec, const LoadOptions& options) {
  const double step = stepBytes(first), budget = double(options.memoryBudget);
  const std::size_t fit = std::size_t(budget / step);
  if (fit < 2)
    throw Error(concat(path.string(), ": a step of the series takes ", formatByteSize(step),
                       " and playback holds two at once, beyond field.memory_budget (",
                       formatByteSize(budget), "); raise field.memory_budget to at least ",
                       budgetValueAtLeast(2.0 * step), " or lower field.resolution"));
  StreamPlan plan;
  plan.capacity = 2 + std::size_t(spec.readAhead);
  if (plan.capacity > fit) {
    log::warn(path.string(), ": field.read_ahead = ", spec.readAhead, " needs ", plan.capacity,
              " steps of ", formatByteSize(step), " in memory, beyond field.memory_budget (",
              formatByteSize(budget), "); reading ", fit - 2, " ahead");
    plan.capacity = fit;
  }
  const std::size_t cores = std::max(2u, std::thread::hardware_concurrency());
  plan.readers = int(std::clamp<std::size_t>(plan.capacity - 2, 1, cores / 2));
  return plan;
}

// field.precision = "auto": the room for a field's grids on the GPU, three
// quarters of the smallest GPU's memory (the rest: particles, the views'
// targets, the driver). The GPUs are asked only for a field whose floats
// would take 64 MiB or more there.
std::optional<double> gpuRoomForFields(double floatBytes) {
  if (floatBytes < double(std::uint64_t{64} << 20)) return std::nullopt;
  const std::optional<std::uint64_t> memory = smallestGpuMemory();
  if (!memory) return std::nullopt;
  return 0.75 * double(*memory);
}

// A source a running simulation writes: its first step, waited for (up to
// wait_s), as a timeline of one frame, and the scanner to watch for more.
FieldSource watchedField(const std::filesystem::path& path, const FieldSpec& spec,
                         const LoadOptions& options) {
  // A folder beside its own .pvd: the steps are timed here by their order,
  // not by the collection's times, which a user opening the folder expects.
  std::error_code listing;
  if (std::filesystem::is_directory(path, listing))
    for (const auto& entry : std::filesystem::directory_iterator(path, listing))
      if (entry.path().extension() == ".pvd") {
        log::warn("field: ", path.string(), " holds the collection ",
                  entry.path().filename().string(), "; the folder is watched, its files timed ",
                  spec.stepInterval, " s apart (field.step_interval) in name order; open ",
                  entry.path().string(), " to play the series at its own times");
        break;
      }
  auto scanner =
      std::make_shared<FieldStreamScanner>(path, spec.stepInterval, 50, spec.settleSeconds);
  const auto until = std::chrono::steady_clock::now() +
                     std::chrono::milliseconds(std::int64_t(spec.waitSeconds * 1e3));
  bool said = false;
  for (;;) {
    std::vector<std::string> messages;
    const std::vector<FieldStreamScanner::Step> found = scanner->poll(messages);
    for (auto it = found.begin(); it != found.end(); ++it) {
      const FieldStreamScanner::Step& step = *it;
      try {
        FieldSource out;
        LoadReport report;
        VectorField loaded = loadField(step.file, options, &report);
        LoadOptions stepOptions = options;
        if (chooseHalf(loaded, kSeriesGrids, options, report)) stepOptions.halfPrecision = true;
        for (const std::string& note : report.notesToLog())
          log::info(path.string(), ": ", note);
        auto field = std::make_shared<const VectorField>(std::move(loaded));
        // Streamed, as a series is: the steps the simulation writes join it
        // and are held only while playback wants them (memory stays flat).
        const StreamPlan plan = streamPlan(path, *field, spec, options);
        auto reader =
            std::make_shared<SeriesReader>(std::vector<SeriesReader::Source>{{step.file, 0}},
                                           stepOptions, field, plan.capacity, plan.readers);
        out.timeline = FieldTimeline({step.time}, reader);
        out.series = reader;
        out.update = FieldUpdate{.field = field, .placement = spec.placement};
        out.stream = scanner;
        out.streamOptions = stepOptions;
        // The steps found with it (the simulation ran before the start) join next.
        scanner->putBack({std::next(it), found.end()});
        out.description =
            concat(path.string(), " (watched; its first step ", step.file.filename().string(),
                   " at t = ", step.time, " s; at most ", plan.capacity, " steps in memory)");
        return out;
      } catch (const Error& e) {
        log::warn("field stream: the step ", step.file.string(), " was skipped: ", e.what());
      }
    }
    for (const std::string& m : messages)
      log::warn("field stream: ", m);
    if (std::chrono::steady_clock::now() > until)
      throw Error(concat("field source ", path.string(), ": no complete step came within ",
                         spec.waitSeconds, " s (field.wait_s)"));
    if (!said) {
      log::info("field: waiting up to ", spec.waitSeconds,
                " s (field.wait_s) for the first step in ", path.string(),
                ": a field file a simulation writes there");
      // A case folder missing its controlDict looks like a watched folder.
      std::error_code ec;
      if (std::filesystem::is_directory(path / "system", ec) ||
          std::filesystem::is_directory(path / "constant", ec))
        log::warn("field: ", path.string(),
                  " has an OpenFOAM case's folders but no system/controlDict, so it is watched "
                  "for field files rather than read as a case");
    }
    said = true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

// A file: one field, or a series (a .pvd, or the steps an Exodus, EnSight,
// OpenFOAM ... file holds) streamed from disk as playback needs its steps.
FieldSource fileField(const std::filesystem::path& path, const FieldSpec& spec,
                      const LoadOptions& options) {
  FieldSource out;
  LoadReport report;
  SeriesIndex index = indexSeries(path, options, &report);
  for (const std::string& note : report.notesToLog())
    log::info(path.string(), ": ", note);
  if (index.times.size() == 1) {
    out.description = concat(path.string(), " (", report.format, ", '", report.arrayName, "')");
    out.update = FieldUpdate{.field = index.first, .placement = spec.placement};
    return out;
  }
  const StreamPlan plan = streamPlan(path, *index.first, spec, options);
  const std::size_t capacity = plan.capacity, steps = index.times.size();
  const int readers = plan.readers;
  const double step = stepBytes(*index.first);
  const double start = index.times.front(), end = index.times.back();
  auto reader = std::make_shared<SeriesReader>(std::move(index.sources), index.stepOptions,
                                               index.first, capacity, readers);
  out.description = concat(path.string(), ": ", steps, " steps over ", end - start, " s ('",
                           report.arrayName, "'), streamed: at most ", capacity, " steps (",
                           formatByteSize(double(capacity) * step), ") in memory, ", readers,
                           readers == 1 ? " reader" : " readers");
  out.timeline = FieldTimeline(std::move(index.times), reader);
  out.series = reader;
  out.update = FieldUpdate{.field = index.first, .placement = spec.placement};
  return out;
}

// An OpenVDB grid kept sparse (field.storage), with a dense overview of it
// for what needs a grid (bounds, colour grids); nullopt for other files, and
// where field.storage = "auto" finds a dense grid as good.
std::optional<FieldSource> sparseField(const std::filesystem::path& path, const FieldSpec& spec,
                                       LoadOptions options) {
  if (spec.storage == FieldSpec::Storage::Dense) return std::nullopt;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec) || detectFieldFormat(path) != FieldFormat::OpenVdb) {
    if (spec.storage == FieldSpec::Storage::Sparse)
      throw Error(concat(path.string(),
                         ": field.storage = \"sparse\" keeps OpenVDB (.vdb) grids sparse; this "
                         "file is another format (field.storage = \"auto\" or \"dense\")"));
    return std::nullopt;
  }
  if (spec.halfPrecision)
    throw Error(concat(path.string(),
                       ": field.precision = \"half\" is for dense grids; a sparse grid keeps "
                       "floats (field.storage = \"dense\" for half precision)"));
  options.sparse =
      spec.storage == FieldSpec::Storage::Sparse ? SparseChoice::Always : SparseChoice::Auto;
  LoadReport report;
  std::optional<SparseField> sparse = readSparseVdb(path, options, report);
  if (!sparse) return std::nullopt;
  for (const std::string& note : report.notesToLog())
    log::info(path.string(), ": ", note);
  FieldSource out;
  auto shared = std::make_shared<const SparseField>(std::move(*sparse));
  const glm::ivec3 top = shared->indexMax() - shared->indexMin() + 1;
  out.description =
      concat(path.string(), " (OpenVDB, '", report.arrayName,
             "', sparse: ", shared->activeVoxelCount(), " active voxels of ", top.x, "x", top.y,
             "x", top.z, ", ", formatByteSize(double(shared->byteSize())), ")");
  out.update = FieldUpdate{
      .field = std::make_shared<const VectorField>(shared->overview(kSparseOverviewPoints)),
      .placement = spec.placement,
      .sparse = shared};
  return out;
}

}  // namespace

FieldSource makeField(const FieldSpec& spec, const std::filesystem::path& baseDir) {
  FieldSource out;
  if (spec.source == "analytic") {
    FieldParams params(spec.params.begin(), spec.params.end());
    const auto analytic = makeAnalyticField(spec.name, params);
    auto field = std::make_shared<VectorField>(bake(*analytic, spec.bounds, spec.dims));
    if (spec.halfPrecision) field->roundToHalf();
    out.description = concat("analytic '", spec.name, "' baked to ", spec.dims.x, "x", spec.dims.y,
                             "x", spec.dims.z);
    if (spec.autoPrecision) {
      // As a file's grid: halves when its floats would not fit the GPU.
      LoadOptions options;
      options.gpuRoom = gpuRoomForFields;
      LoadReport report;
      chooseHalf(*field, 1, options, report);
      for (const std::string& note : report.notesToLog())
        log::info("field: ", out.description, ": ", note);
    }
    out.update = FieldUpdate{.field = std::move(field), .placement = spec.placement};
    if (auto equation = fieldEquation(*analytic))
      out.update.equation = std::make_shared<FieldEquation>(*equation);
  } else {
    const std::filesystem::path path = resolve(spec.source, baseDir);
    LoadOptions options;
    options.arrayName = spec.name;
    options.resolution = spec.resolution;
    options.memoryBudget = std::size_t(fieldMemoryBudget(spec));
    options.halfPrecision = spec.halfPrecision;
    if (spec.autoPrecision) options.gpuRoom = gpuRoomForFields;
    std::error_code ec;
    // A large file's question to the GPUs is asked while the file is read
    // (a 512^3 file's walls started 0.07-0.27 s sooner on NVIDIA), and the
    // walls' contexts then start on displays already open.
    std::future<void> asked;
    if (spec.autoPrecision && !std::filesystem::is_directory(path, ec) &&
        std::filesystem::file_size(path, ec) >= (std::uintmax_t{64} << 20) && !ec)
      asked = std::async(std::launch::async, [] { smallestGpuMemory(); });
    // A folder is watched for steps, unless it is an OpenFOAM case.
    if (spec.watch || (std::filesystem::is_directory(path, ec) &&
                       detectFieldFormat(path) != FieldFormat::OpenFoam)) {
      out = watchedField(path, spec, options);
    } else if (auto sparse = sparseField(path, spec, options)) {
      out = std::move(*sparse);
    } else {
      out = fileField(path, spec, options);
    }
  }
  const VectorField& f = *out.update.field;
  log::info("field: ", out.description, ", ", f.dims().x, "x", f.dims().y, "x", f.dims().z,
            " over [", f.bounds().min.x, ",", f.bounds().min.y, ",", f.bounds().min.z, "]..[",
            f.bounds().max.x, ",", f.bounds().max.y, ",", f.bounds().max.z, "] m, max speed ",
            f.maxMagnitude(), " m/s");
  // A file's field at rest carries nothing: say so, since the picture alone
  // looks like a bug (particles where they were seeded, the legend at 0). An
  // analytic one is as the configuration asked ('still': the field editor's
  // blank canvas).
  if (f.maxMagnitude() == 0.0f && spec.source != "analytic")
    log::warn("field: ", out.description, ": the velocity is 0 everywhere",
              out.timeline ? " in its first step" : "",
              ", so particles stay where they are seeded; if another array holds the flow, "
              "name it (--array NAME, or the config's field.name)");
  return out;
}

void useField(MainContext& main, const FieldSource& source) {
  if (source.timeline)
    main.setFieldTimeline(*source.timeline, source.update.placement);
  else
    main.setField(source.update);
}

std::vector<std::string> fieldChoices(const std::filesystem::path& dataDir,
                                      const std::filesystem::path& base) {
  std::vector<std::string> choices;
  for (const AnalyticFieldSpec& spec : analyticFieldSpecs())
    choices.push_back("analytic:" + spec.name);
  std::error_code ec;
  std::vector<std::string> files;
  for (auto it = std::filesystem::recursive_directory_iterator(dataDir, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    const std::string ext = it->path().extension().string();
    const bool inSeries = it->path().parent_path().filename() == "series" && ext != ".pvd";
    if (!inSeries && hasFieldExtension(it->path()))
      files.push_back(std::filesystem::relative(it->path(), base).string());
  }
  std::sort(files.begin(), files.end());
  choices.insert(choices.end(), files.begin(), files.end());
  return choices;
}

FieldSpec fieldSpecFor(const std::string& choice, const FieldSpec& base) {
  FieldSpec spec = base;
  spec.params.clear();
  if (choice.starts_with("analytic:")) {
    spec.source = "analytic";
    spec.name = choice.substr(9);
  } else {
    spec.source = choice;
    spec.name.clear();
  }
  return spec;
}

std::shared_ptr<const HeightMap> makeTerrain(const SceneSpec& spec,
                                             const std::filesystem::path& baseDir) {
  if (spec.terrain == "flat") {
    // 10 km each way from the origin, or as far as terrain_min..terrain_max
    // reach (a field kilometres wide, away from the origin).
    const glm::vec3 far =
        glm::max(glm::abs(spec.terrainBounds.min), glm::abs(spec.terrainBounds.max));
    return std::make_shared<HeightMap>(
        HeightMap::flat(spec.groundHeight, std::max({1e4f, far.x, far.y})));
  }
  if (!spec.terrain.ends_with(".pgm"))
    throw Error(concat("scene.terrain '", spec.terrain,
                       "': expected \"flat\" or a 16-bit height map (.pgm)"));
  auto map = std::make_shared<HeightMap>(
      readHeightMapPgm(resolve(spec.terrain, baseDir), spec.terrainBounds));
  log::info("terrain: ", spec.terrain, ", ", map->dims().x, "x", map->dims().y, " over ",
            spec.terrainBounds.max.x - spec.terrainBounds.min.x, " m, heights ", map->minHeight(),
            "..", map->maxHeight(), " m");
  return map;
}

}  // namespace sandstorm
