#include "app/app.h"

#include <algorithm>
#include <cstdlib>
#include <utility>

#include "app/app_run.h"
#include "app/cluster/cluster_link.h"
#include "app/movie_recorder.h"
#include "contexts/platform/software_rasterizer.h"
#include "core/config/config_sets.h"
#include "core/sim/attribute_table.h"
#include "core/sim/session_log.h"
#include "core/util/error.h"
#include "core/util/log.h"
#include "core/util/output_file.h"

namespace sandstorm {
namespace {

bool haveDisplay() {
  const char* x = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (wayland && *wayland);
}

constexpr int kHeadlessFrames = 240;

}  // namespace

void checkRunOutputs(const AppOptions& options) {
  const std::pair<const std::optional<std::filesystem::path>&, const char*> outputs[] = {
      {options.dumpParticles, "--dump-particles"},
      {options.dumpStreamlines, "--dump-streamlines"},
      {options.dumpTrails, "--dump-trails"},
      {options.hashLog, "--hash-log"},
      {options.stats, "--stats"},
      {options.saveField, "--save-field"},
      {options.bakeField, "--bake-field"},
      {options.record, "--record"}};
  for (const auto& [path, option] : outputs)
    if (path) checkOutputFile(*path, option);
}

void checkRunFiles(const AppOptions& options) {
  checkRunOutputs(options);
  if (options.replay) readSession(*options.replay);
}

void applySets(AppConfig& config, const std::vector<std::string>& sets) {
  const AttributeTable& table = AttributeTable::instance();
  for (const std::string& set : sets) {
    const std::size_t eq = set.find('=');
    if (eq == std::string::npos || eq == 0)
      throw Error(concat("--set '", set, "': expected key=value, e.g. --set emitter.0.rate=50000"));
    const std::string key = set.substr(0, eq);
    if (isConfigSetting(key)) continue;  // read with the configuration (applyConfigSets)
    const AttributeResult r =
        table.set(config.particles, key, table.parse(key, set.substr(eq + 1)));
    if (!r.warning.empty()) log::warn("--set ", r.warning);
  }
}

bool opensWindows(const AppConfig& config, const AppOptions& options) {
  const bool movieSize = options.movie && options.movie->size;
  return config.anyWindow() && !options.headless && !movieSize && haveDisplay();
}

App::App(AppConfig config, AppOptions options, ClusterLink* cluster,
         std::optional<FieldSource> field)
    : config_(std::move(config)),
      options_(std::move(options)),
      cluster_(cluster),
      field_(std::move(field)) {
  // A movie of its own size is a render job: its walls are drawn offscreen.
  const bool movieSize = options_.movie && options_.movie->size;
  headless_ = options_.headless || movieSize || !haveDisplay();
  if (headless_) {
    if (config_.anyWindow() && !options_.headless)
      log::info("no display: rendering the windows offscreen instead");
    for (WallSpec& w : config_.walls) {
      if (w.window) w.offscreenSize = w.window->size;
      w.window.reset();
      if (w.stereo == StereoMode::QuadBuffer) w.stereo = StereoMode::SideBySide;
    }
  }
  if (!options_.walls.empty()) {
    std::vector<WallSpec> chosen;
    for (const std::string& name : options_.walls) {
      const auto it = std::find_if(config_.walls.begin(), config_.walls.end(),
                                   [&](const WallSpec& w) { return w.name == name; });
      if (it == config_.walls.end()) {
        std::string known;
        for (const WallSpec& w : config_.walls)
          known += (known.empty() ? "" : ", ") + w.name;
        throw Error(concat("--walls: no wall named '", name, "' in ", config_.path.string(),
                           "; it has ", known));
      }
      chosen.push_back(*it);
    }
    config_.walls = std::move(chosen);
  }
  if (options_.movie) MovieRecorder::prepareWalls(config_, *options_.movie);
  const bool offscreenOnly = !config_.anyWindow();
  if (options_.frames) config_.run.frames = *options_.frames;
  // Without windows nothing closes: a run of its own is kHeadlessFrames long,
  // while an explicit --frames 0 runs until Ctrl-C or SIGTERM.
  if (offscreenOnly && config_.run.frames == 0 && !options_.frames)
    config_.run.frames = kHeadlessFrames;
  if (offscreenOnly && !options_.screenshotDir && !options_.movie) options_.screenshotDir = "out";
  if (offscreenOnly && config_.run.fixedDt == 0.0f) config_.run.fixedDt = 1.0f / 60.0f;
  applySets(config_, options_.sets);
  // Offscreen there is nobody at a mouse: the menu shows when a script or a tracked wand drives it.
  if (headless_ && !options_.menuScript && config_.tracking.source == TrackingSource::None &&
      !(options_.movie && options_.movie->menu))
    options_.noMenu = true;
  // --movie-menu: a menu in the movie, on its first wall unless a wall is the menu's.
  if (options_.movie && options_.movie->menu && !options_.noMenu && !config_.walls.empty() &&
      std::none_of(config_.walls.begin(), config_.walls.end(),
                   [](const WallSpec& w) { return w.menu; }))
    config_.walls.front().menu = true;
  if (options_.noMenu) {
    config_.menu.operatorWindow.reset();
    for (WallSpec& w : config_.walls)
      w.menu = false;
  }
}

int App::run() {
  if (cluster_) cluster_->localize(config_, options_);  // this rank's walls and outputs
  keepSoftwareRasterizingInDrawingThreads(config_.glContexts());
  AppRun run(config_, options_, headless_, cluster_, std::exchange(field_, std::nullopt));
  run.setFieldSeeding(std::move(seeding_));
  return run.execute();
}

}  // namespace sandstorm
