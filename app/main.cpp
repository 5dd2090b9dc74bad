// sandstorm: the application. See README.md and `sandstorm --help`.
#include <CLI/CLI.hpp>

#include "app/app.h"
#include "app/cli_numbers.h"
#include "app/cli_unknown_option.h"
#include "app/cluster/cluster_link.h"
#include "app/default_config.h"
#include "app/file_scene.h"
#include "app/load_with_window.h"
#include "contexts/platform/gpu_memory.h"
#include "core/config/config_sets.h"
#include "core/io/field_loader.h"
#ifdef SANDSTORM_MPI
#include "app/cluster/cluster_main.h"
#endif
#include "core/util/error.h"
#include "core/util/log.h"

int main(int argc, char** argv) {
  using namespace sandstorm;
  CLI::App cli{
      "Sandstorm: GPU particles carried through vector fields, for CAVEs and multi-window walls"};
  std::string configPath = "config/downdraft.toml";
  AppOptions options;
  std::string screenshotDir, dumpPath, logLevel;
  int frames = -1;
  CLI::Option* configOption = cli.add_option("-c,--config", configPath, "Configuration file (TOML)")
                                  ->check(CLI::ExistingFile);
  std::string fieldFile, arrayName;
  cli.add_option("field,--field", fieldFile,
                 "Open this field file as ParaView does: in the desktop scene, or in --config's "
                 "walls. VTK (.vti .vtr .vts .vtu .vtp .vtk, parallel .pvt?, multiblock .vtm, "
                 "series .pvd), Exodus II (.e), EnSight Gold (.case), an OpenFOAM case, NetCDF "
                 "CF (.nc), CGNS (.cgns), VTKHDF (.vtkhdf), OpenVDB (.vdb), Unreal (.fga), "
                 "Unity (.vf)")
      ->check(CLI::ExistingPath);
  cli.add_option("--array", arrayName,
                 "The field file's vector array or grid (a file with several asks for one), or "
                 "three components joined: u,v,w");
  cli.add_option("-n,--frames", frames,
                 "Frames to run, then exit (0: until a window closes, or Ctrl-C)")
      ->check(wholeNumberCheck(0));
  cli.add_option("--screenshot", screenshotDir, "Write each wall's last frame as DIR/<wall>.png");
  cli.add_option("--screenshot-every", options.screenshotEvery,
                 "Also write DIR/<wall>_<frame>.png every N frames")
      ->check(wholeNumberCheck(0));
  cli.add_option("--dump-particles", dumpPath,
                 "Write the last frame's particles as VTK PolyData (.vtp)");
  std::string streamlinePath, trailPath;
  cli.add_option("--dump-trails", trailPath,
                 "Write the last frame's particle trails (render.trail_length) as VTK PolyData "
                 "polylines (.vtp)");
  cli.add_option("--dump-streamlines", streamlinePath,
                 "Write the last frame's streamlines (the [streamlines] rake) as VTK PolyData "
                 "polylines (.vtp)");
  std::string saveField, bakeField;
  cli.add_option("--save-field", saveField,
                 "At the end, write the field editor's composition (the [field] and its "
                 "[[primitive]]s) as a configuration block (.toml) that loads back the same");
  cli.add_option("--bake-field", bakeField,
                 "At the end, write the field in use (with the editor's primitives) as a grid "
                 "file (.vti or .vdb)");
  std::string moviePath, movieWall, movieStereo = "left", movieSize;
  double movieFps = 0.0;
  int movieCrf = -1;
  bool movieMenu = false;
  cli.add_option("--movie", moviePath,
                 "Write the run as a movie: FILE.mp4 (H.264) or FILE.webm (VP9), one frame a "
                 "frame at 1/run.fixed_dt frames per second");
  cli.add_option("--movie-wall", movieWall,
                 "The wall the movie shows (default: the first), or 'all': every wall unfolded "
                 "as the CAVE's cross");
  cli.add_option("--movie-stereo", movieStereo,
                 "A stereo wall's left eye, or both eyes side by side: left or side-by-side");
  cli.add_option("--movie-size", movieSize,
                 "The movie's size, WIDTHxHEIGHT: its walls are drawn offscreen for it (e.g. a "
                 "recorded session replayed into 3840x2160)");
  CLI::Option* movieFpsOption =
      cli.add_option("--movie-fps", movieFps, "The movie's frame rate (default: 1/run.fixed_dt)");
  CLI::Option* movieCrfOption =
      cli.add_option("--movie-crf", movieCrf,
                     "The movie's quality: lower is better and larger; H.264 0-51 (default 13), "
                     "VP9 0-63 (default 20)");
  cli.add_flag("--movie-menu", movieMenu, "Show the menu panel in the movie");
  cli.add_option("--set", options.sets,
                 "Set an attribute, e.g. --set emitter.0.rate=50000 (repeatable)");
  std::string hashLog;
  cli.add_option("--hash-log", hashLog,
                 "Write each frame's particle count and buffer hash per wall to FILE");
  cli.add_option("--walls", options.walls, "Run only these walls of the configuration (by name)")
      ->delimiter(',');
  std::string statsPath;
  cli.add_option("--stats", statsPath,
                 "Write the run's frame times and per-wall GPU stage times (after "
                 "run.stats_warmup frames) to FILE as JSON");
  std::string record, replay;
  cli.add_option("--record", record, "Record every attribute change with its frame to FILE");
  cli.add_option("--replay", replay, "Replay a recorded session: its changes at their frames")
      ->check(CLI::ExistingFile);
  std::string menuScript;
  cli.add_option("--menu-script", menuScript,
                 "Scripted clicks on the menu panel (see app/menu/menu_script.h)")
      ->check(CLI::ExistingFile);
  cli.add_flag("--no-menu", options.noMenu, "Show no menu panel");
  cli.add_flag("--headless", options.headless,
               "Render every wall offscreen (EGL), even with a display");
  bool cluster = false;
  ClusterOptions clusterOptions;
  cli.add_flag("--cluster", cluster,
               "Cluster mode (MPI), as when started by mpirun (which is detected)");
  cli.add_flag("--cluster-stats", clusterOptions.stats,
               "Cluster mode: log broadcast bytes and times per frame at the end");
  cli.add_option("--cluster-bench", clusterOptions.benchFrames,
                 "Cluster mode: N frames of packets and swap barriers only (no walls); use with "
                 "--cluster-stats")
      ->check(wholeNumberCheck(0));
  // Fault injection for the cluster tests; hidden from --help.
  cli.add_option("--debug-rank", clusterOptions.debugRank)->group("");
  cli.add_option("--debug-die-at-frame", clusterOptions.dieAtFrame)->group("");
  cli.add_option("--debug-hang-at-frame", clusterOptions.hangAtFrame)->group("");
  cli.add_option("--debug-corrupt-at-frame", clusterOptions.corruptAtFrame)->group("");
  cli.add_flag("--debug-blind-to-steps", clusterOptions.blindToSteps)->group("");
  // Answers the GPU memory question (field.precision = "auto") with this many bytes.
  std::uint64_t pretendedGpuMemory = 0;
  cli.add_option("--debug-gpu-memory", pretendedGpuMemory)->group("");
  cli.add_option("--log-level", logLevel, "error, warn, info or debug")
      ->check(CLI::IsMember({"error", "warn", "info", "debug"}));
  if (const std::string unknown = unknownOption(cli, argc, argv); !unknown.empty()) {
    log::error(unknown);
    return 2;
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cli.exit(e);
  }
  if (configOption->count() == 0) configPath = defaultConfig("downdraft.toml").string();
  if (pretendedGpuMemory > 0) pretendGpuMemory(pretendedGpuMemory);
  if (!logLevel.empty()) {
    log::Level level;
    log::parseLevel(logLevel, level);
    log::setLevel(level);
  }
  if (frames >= 0) options.frames = frames;
  if (!screenshotDir.empty()) options.screenshotDir = screenshotDir;
  if (!hashLog.empty()) options.hashLog = hashLog;
  if (!record.empty()) options.record = record;
  if (!statsPath.empty()) options.stats = statsPath;
  if (!replay.empty()) options.replay = replay;
  if (!menuScript.empty()) options.menuScript = menuScript;
  if (!dumpPath.empty()) {
    if (!dumpPath.ends_with(".vtp")) {
      log::error("--dump-particles ", dumpPath, ": expected a .vtp file name");
      return 2;
    }
    options.dumpParticles = dumpPath;
  }
  if (!streamlinePath.empty()) {
    if (!streamlinePath.ends_with(".vtp")) {
      log::error("--dump-streamlines ", streamlinePath, ": expected a .vtp file name");
      return 2;
    }
    options.dumpStreamlines = streamlinePath;
  }
  if (!saveField.empty()) {
    if (!saveField.ends_with(".toml")) {
      log::error("--save-field ", saveField, ": expected a .toml file name");
      return 2;
    }
    options.saveField = saveField;
  }
  if (!bakeField.empty()) {
    if (!bakeField.ends_with(".vti") && !bakeField.ends_with(".vdb")) {
      log::error("--bake-field ", bakeField, ": expected a .vti or .vdb file name");
      return 2;
    }
    options.bakeField = bakeField;
  }
  if (!trailPath.empty()) {
    if (!trailPath.ends_with(".vtp")) {
      log::error("--dump-trails ", trailPath, ": expected a .vtp file name");
      return 2;
    }
    options.dumpTrails = trailPath;
  }
  try {
    if (!moviePath.empty()) {
      options.movie = movieSpecFrom(
          {.path = moviePath,
           .wall = movieWall,
           .stereo = movieStereo,
           .size = movieSize.empty() ? std::nullopt : std::optional<std::string>(movieSize),
           .fps = movieFpsOption->count() > 0 ? std::optional<double>(movieFps) : std::nullopt,
           .crf = movieCrfOption->count() > 0 ? std::optional<int>(movieCrf) : std::nullopt,
           .menu = movieMenu});
    } else if (!movieWall.empty() || !movieSize.empty() || movieFpsOption->count() > 0 ||
               movieCrfOption->count() > 0 || movieMenu || movieStereo != "left") {
      throw Error(
          "--movie-wall, --movie-stereo, --movie-size, --movie-fps, --movie-crf and "
          "--movie-menu shape a movie: give --movie FILE too");
    }
  } catch (const Error& e) {
    log::error(e.what());
    return 2;
  }
#ifdef SANDSTORM_MPI
  if (!fieldFile.empty() && (cluster || launchedByMpirun())) {
    log::error(fieldFile,
               ": cluster mode opens fields from its configuration's [field]; "
               "give the file there");
    return 2;
  }
  if (cluster || launchedByMpirun()) return runCluster(configPath, options, clusterOptions);
#else
  if (cluster) {
    log::error(
        "--cluster: this sandstorm was built without MPI (scripts/setup installs Open MPI; "
        "rebuild)");
    return 1;
  }
#endif
  try {
    checkRunFiles(options);
    if (!fieldFile.empty()) {
      // The desktop scene unless a configuration was named.
      AppConfig config = loadConfig(
          configOption->count() > 0 ? configPath : defaultConfig("desktop.toml").string());
      pointAtFile(config, fieldFile, arrayName, options.sets);  // and applies the --sets
      if (const std::optional<VtkImageFrame> frame = fileSceneFrame(config.field)) {
        // Framed from the file's header: the walls open while the file is read.
        const int maximum = config.particles.sim.maximum;
        frameFileScene(config, fieldFile, frame->bounds(), frame->dims());
        App app(std::move(config), options);
        app.setFieldSeeding(seedFileScene(fieldFile, *frame, maximum, options.sets));
        return app.run();
      }
      FieldSource field = loadWithWindow([&] { return makeField(config.field, config.folder); },
                                         opensWindows(config, options));
      openFileScene(config, fieldFile, *field.update.field);
      App app(std::move(config), options, nullptr, std::move(field));
      return app.run();
    }
    if (!arrayName.empty())
      throw Error("--array " + arrayName + ": names an array of a field file; give the file too");
    AppConfig config = loadConfig(configPath);
    applyConfigSets(config, options.sets);
    // The run reads the field while its walls open; windows show the read's progress.
    App app(std::move(config), options);
    return app.run();
  } catch (const Error& e) {
    log::error(e.what());
    return 1;
  } catch (const std::exception& e) {
    log::error("unexpected: ", e.what());
    return 1;
  }
}
