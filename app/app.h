// App: the thin top of Sandstorm. It settles the configuration against the
// command line (headless, --walls, --set, the menu), then hands one run to
// AppRun (app_run.h): the main context, a render context (thread + GL context)
// per wall, and the frame loop.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/scene_setup.h"
#include "core/config/app_config.h"
#include "core/movie/movie_spec.h"

namespace sandstorm {

class ClusterLink;

struct AppOptions {
  std::optional<int> frames;  // overrides run.frames
  std::optional<std::filesystem::path> screenshotDir;
  int screenshotEvery = 0;  // also every N frames (0: only the last)
  std::optional<std::filesystem::path> dumpParticles;
  std::optional<std::filesystem::path> dumpStreamlines;  // the last frame's streamlines (.vtp)
  std::optional<std::filesystem::path> dumpTrails;       // the last frame's trails (.vtp)
  std::vector<std::string> sets;                         // "key=value" attribute overrides
  bool headless = false;                                 // force offscreen walls
  std::optional<std::filesystem::path>
      hashLog;                     // per frame and wall: particle count and buffer hash
  std::vector<std::string> walls;  // run only these walls (empty: all)
  std::optional<std::filesystem::path> record;  // write every change with its frame
  std::optional<std::filesystem::path>
      replay;  // apply a recorded session's changes at their frames
  std::optional<std::filesystem::path> menuScript;  // scripted clicks on the menu (tests, demos)
  bool noMenu = false;
  std::optional<std::filesystem::path> stats;  // --stats: the run's measurements as JSON
  // The field editor at the end of the run: its composition as a configuration
  // block (.toml), the composed field as a grid file (.vti or .vdb).
  std::optional<std::filesystem::path> saveField, bakeField;
  std::optional<MovieSpec> movie;  // --movie and its options
};

// Tries every file the run will write (--dump-*, --stats, --record, ...), so
// that a bad path stops the start, not the end. Throws Error naming the option.
void checkRunOutputs(const AppOptions& options);
// checkRunOutputs(), and reads the session to replay: before a field file is
// read (a large one takes minutes), so a bad path or session stops it first.
void checkRunFiles(const AppOptions& options);

// Applies --set overrides to the configuration's particle state. Throws Error.
void applySets(AppConfig& config, const std::vector<std::string>& sets);

// Whether a run of `config` with `options` opens windows: it has a window,
// there is a display, and neither --headless nor a movie of its own size
// draws offscreen.
bool opensWindows(const AppConfig& config, const AppOptions& options);

class App {
 public:
  // `cluster`: cluster mode (app/cluster/), this rank's link to the others; null: one process.
  // `field`: the configuration's [field], already read (fileSceneField); empty: the run reads it.
  App(AppConfig config, AppOptions options, ClusterLink* cluster = nullptr,
      std::optional<FieldSource> field = std::nullopt);
  // Once the run's field is read, before packet 0 (sandstorm FILE framed from its header).
  void setFieldSeeding(FieldSeeding seeding) { seeding_ = std::move(seeding); }
  // Runs until the frame count is reached, a window closes or Ctrl-C. Returns
  // the process exit code (0, or 1 when a wall failed).
  int run();

  const AppConfig& config() const { return config_; }
  const AppOptions& options() const { return options_; }

 private:
  AppConfig config_;
  AppOptions options_;
  ClusterLink* cluster_ = nullptr;
  bool headless_ = false;
  std::optional<FieldSource> field_;  // moves into the run
  FieldSeeding seeding_;
};

}  // namespace sandstorm
