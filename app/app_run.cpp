#include "app/app_run.h"

#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <map>
#include <thread>

#include "app/cluster/cluster_link.h"
#include "app/run_stats.h"
#include "app/wall_lines.h"
#include "contexts/particles/simulation_share.h"
#include "contexts/platform/egl_context.h"
#include "core/cave/wall_views.h"
#include "core/config/byte_size.h"
#include "core/flow/probe.h"
#include "core/flow/streamline_vtp.h"
#include "core/io/series_reader.h"
#include "core/obstacles/collision_shapes.h"
#include "core/sim/particle_dump.h"
#include "core/util/error.h"
#include "core/util/log.h"
#include "core/util/output_file.h"

namespace sandstorm {
namespace {

std::atomic<bool> interrupted{false};

void onInterrupt(int) {
  interrupted = true;
}

GlfwWindow::Options windowOptions(const std::string& title, const WindowSpec& w) {
  GlfwWindow::Options o;
  o.title = title;
  o.size = w.size;
  o.position = w.position;
  o.monitor = w.monitor;
  o.fullscreen = w.fullscreen;
  o.decorated = w.decorated;
  return o;
}

// Frames left out of the run statistics: run.stats_warmup, or where the run
// is no longer than that (a short run asked for its stage times), its first
// half, said in the log (not as a warning: `--frames 1` is an ordinary
// run), rather than nothing measured.
std::uint32_t statsWarmup(const RunSpec& run) {
  if (run.frames <= 0 || run.frames > run.statsWarmup) return std::uint32_t(run.statsWarmup);
  log::info("run.stats_warmup (", run.statsWarmup, ") is not shorter than the run's ", run.frames,
            " frames: the statistics leave out its first ", run.frames / 2, " instead");
  return std::uint32_t(run.frames / 2);
}

MainContext::Options mainOptions(const AppConfig& config) {
  MainContext::Options o;
  o.seed = config.run.seed;
  o.fixedDt = config.run.fixedDt;
  o.capacityLimit = config.run.capacityLimit;
  o.uploadAhead = config.field.uploadAhead;
  return o;
}

}  // namespace

AppRun::AppRun(const AppConfig& config, const AppOptions& options, bool headless,
               ClusterLink* cluster, std::optional<FieldSource> field)
    : config_(config),
      options_(options),
      headless_(headless),
      cluster_(cluster),
      configDir_(config.folder),
      // The project's data/ sits beside config/.
      projectRoot_(configDir_.parent_path()),
      lastFrame_(config.run.frames > 0 ? config.run.frames - 1 : -1),
      statsWarmup_(statsWarmup(config.run)),
      field_(field ? std::move(*field) : FieldSource{}),
      // In cluster mode only rank 0 makes the field (unless every rank reads it): it travels in
      // packets.
      fieldRead_(
          !field && (!cluster || cluster->makesField())
              ? std::async(std::launch::async,
                           [spec = config.field, dir = configDir_] { return makeField(spec, dir); })
              : std::future<FieldSource>()),
      terrain_(makeTerrain(config.scene, configDir_)),
      main_(config.particles, FieldUpdate{}, mainOptions(config)),  // the field: takeField()
      helicopter_(terrain_),
      fluid_(terrain_),
      editor_(config.field),
      obstaclePaths_(config.obstaclePaths),
      head_(makeHeadTracker(config.head)),
      navigation_(Navigation::from(config.navigation)),
      channel_(int(config.walls.size())),
      // Cluster mode: the main thread joins the swap barrier, to hold the walls until every rank
      // drew.
      barrier_(std::ptrdiff_t(config.walls.size()) + (cluster ? 1 : 0)) {
  // Every output is tried before anything runs: a bad path stops the start, not the end.
  if (options_.screenshotDir) {
    checkOutputDirectory(*options_.screenshotDir, "--screenshot");
    images_ = std::make_unique<ImageFiles>(
        std::clamp<unsigned>(std::thread::hardware_concurrency(), 1,
                             unsigned(std::max<std::size_t>(1, config.walls.size()))));
  }
  checkRunOutputs(options_);  // the session to replay is read below
  if (options_.movie) {
    if (cluster_)
      throw Error(
          "--movie: cluster mode does not write movies; record the session (--record) and "
          "replay it in one process into a movie (--replay FILE --movie FILE --movie-size WxH)");
    movie_ = std::make_unique<MovieRecorder>(*options_.movie, config.walls, config.run);
  }
  if (options_.record) {
    recorder_ = std::make_unique<SessionRecorder>(*options_.record);
    main_.setChangeListener(
        [this](std::uint32_t frame, const StateChange& c) { recorder_->record(frame, c); });
    main_.setFieldWaitListener([this](std::uint32_t frame) { recorder_->recordFieldWait(frame); });
  }
  if (options_.replay) {
    replay_ = readSession(*options_.replay);
    main_.replayFieldWaits(replay_.fieldWaits);
    for (const ScheduledChange& s : replay_.changes)
      main_.schedule(s.frame, s.change);
  }
  if ((!cluster_ || cluster_->root()) && TrackingInput::wanted(config.tracking, replay_.tracking))
    tracking_ =
        std::make_unique<TrackingInput>(config.tracking, config.navigation, replay_.tracking);
}

AppRun::~AppRun() {
  channel_.close();
}

void AppRun::takeField() {
  if (fieldRead_.valid()) {
    // Windows stay answered while the read goes on (their walls show its progress).
    if (glfw_)
      while (fieldRead_.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready)
        GlfwLibrary::pollEvents();
    field_ = fieldRead_.get();  // what the read threw, start() throws
  }
  useField(main_, field_);
  // The walls upload it while packet 0 is prepared (a 512^3 grid's upload,
  // 0.11 s on an H200, beside the seeding's pass over it). Not where packet
  // 0 brings another: a cluster's, from rank 0's broadcast; the helicopter's
  // wash or the editor's primitives added to it below.
  const ParticleState pending = main_.state();
  const bool replaced = pending.helicopter.enabled ||
                        std::any_of(pending.primitives.begin(), pending.primitives.end(),
                                    [](const FieldPrimitive& p) { return p.active(); });
  if (!cluster_ && !replaced) channel_.offerField(main_.field());
  if (cluster_ && !cluster_->root()) return;
  if (seeding_ && !options_.replay) seeding_(main_, field_);  // a session holds its changes
  helicopter_.update(main_);  // the configured helicopter's field and dust, before packet 0
  editor_.update(main_);      // the configuration's [[primitive]]s, before packet 0 too
  // A replayed session holds the paths' moves (they were recorded as changes).
  if (!options_.replay) obstaclePaths_.start(main_);
  // A watched field: its steps come from a thread (a replay has them in the session).
  if (field_.stream && !options_.replay)
    fieldStream_ = std::make_unique<FieldStream>(field_.stream, field_.streamOptions,
                                                 [this] { return main_.nextFrame(); });
}

int AppRun::execute() {
  if (!start()) return 1;
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
  if (cluster_)
    runCluster();
  else
    while (advance()) {
    }
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  return stop();
}

bool AppRun::start() {
  openWindowLibrary();
  // A field read within a moment is taken first: a small file's error comes
  // before any wall opens. A longer read goes on while the walls open (on
  // NVIDIA 0.2-0.3 s of contexts, programs and buffers).
  const bool readAWhile =
      fieldRead_.valid() &&
      fieldRead_.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready;
  if (!readAWhile) takeField();
  openWalls();  // their threads open them, then wait for packet 0
  if (readAWhile) {
    log::debug("the walls open while the field is read");
    if (!windows_.empty()) log::info("loading: the progress shows on the walls' windows too");
    takeField();
  }
  std::vector<GLFWwindow*> inputWindows;
  for (GlfwWindow* w : windows_)
    inputWindows.push_back(w->handle());
  input_ = std::make_unique<DesktopInput>(inputWindows);  // before the menu's ImGui callbacks
  input_->setPicker([this](const DesktopInput::Click& click) {
    const std::optional<WorldRay> ray = rayThrough(click);
    return ray && (obstacleDrag_.pick(main_.pendingState(), *ray) ||
                   moleculePush_.press(main_, *ray, fieldCentre(*ray)));
  });
  openMenu();
  openLegend();
  if (cluster_) {
    if (!cluster_->ready("")) return false;  // some rank could not open its walls; rank 0 said why
    cluster_->shareField(field_);
  }
  hookWalls();
  interrupted = false;
  start_ = lastReport_ = lastTick_ = Clock::now();
  return true;
}

int AppRun::stop() {
  channel_.close();
  for (auto& c : contexts_)
    c->join();
  return finish();
}

void AppRun::openWindowLibrary() {
  operatorWindow_ = config_.menu.operatorWindow && !headless_;
  if (!config_.anyWindow() && !operatorWindow_) return;
  glfw_ = std::make_unique<GlfwLibrary>();
  // Every window's monitor exists, or nothing starts.
  const int monitors = glfw_->monitorCount();
  for (std::size_t i = 0; i < config_.walls.size(); ++i) {
    const WallSpec& w = config_.walls[i];
    if (w.window && w.window->monitor >= std::max(monitors, 1))
      throw Error(concat(config_.path.string(), ":", w.line, ": wall[", i,
                         "].window.monitor: monitor ", w.window->monitor, " does not exist; ",
                         monitors, " connected"));
  }
}

// The GPU each wall draws on: -1 for windows (their display's), else the
// wall's `gpu`, or run.gpus's choice.
std::vector<int> AppRun::wallGpus() const {
  std::vector<int> gpus;
  int offscreen = 0;
  const int available = config_.run.gpusRoundRobin ? EglContext::deviceCount() : 1;
  for (const WallSpec& w : config_.walls) {
    if (w.window)
      gpus.push_back(-1);
    else
      gpus.push_back(w.gpu.value_or(offscreen % available));
    offscreen += w.window ? 0 : 1;
  }
  return gpus;
}

void AppRun::openWalls() {
  const int wallCount = int(config_.walls.size());
  wallWindows_.assign(std::size_t(wallCount), nullptr);
  const std::vector<int> gpus = wallGpus();
  // One simulation per GPU: windows share objects with the first window, the
  // offscreen walls of a GPU with its first offscreen wall (GLX and EGL
  // contexts cannot share, nor can two GPUs).
  struct ShareGroup {
    const GlContext* owner = nullptr;
    std::shared_ptr<SimulationShare> share;
    int readers = 0;
    RenderContext* offscreen = nullptr;  // the context drawing this GPU's offscreen walls
  };
  std::map<int, ShareGroup> groups;  // by GPU, -1: windows
  for (int gpu : gpus)
    ++groups[gpu].readers;
  const auto offscreenGpus =
      std::ranges::count_if(groups, [](const auto& g) { return g.first >= 0; });
  if (offscreenGpus > 2)
    log::warn("this process draws on ", offscreenGpus,
              " GPUs, whose GL threads take turns on a lock of the driver (NVIDIA's, measured: "
              "four GPUs in one process are slower than one); run one rank a GPU in cluster "
              "mode instead (mpirun, [[wall]] rank and gpu; docs/CLUSTER.md)");
  for (auto& [gpu, g] : groups)
    if (g.readers-- > 0 && config_.run.sharedSimulation)
      g.share = std::make_shared<SimulationShare>(g.readers);
  // Offscreen walls draw from one context a GPU (run.offscreen_contexts = "one"):
  // contexts on one GPU take turns on it, at a cost far above their work.
  const bool oneOffscreenContext = config_.run.offscreenContexts == RunSpec::OffscreenContexts::One;
  for (int i = 0; i < wallCount; ++i) {
    const WallSpec& spec = config_.walls[std::size_t(i)];
    const int gpu = gpus[std::size_t(i)];
    ShareGroup& group = groups[gpu];
    std::unique_ptr<GlContext> context;
    if (spec.window) {
      GlfwWindow::Options o = windowOptions("Sandstorm: " + spec.name, *spec.window);
      o.quadBufferStereo = spec.stereo == StereoMode::QuadBuffer;
      o.share = static_cast<const GlfwWindow*>(group.owner);
      auto window = std::make_unique<GlfwWindow>(*glfw_, o);
      windows_.push_back(window.get());
      wallWindows_[std::size_t(i)] = window.get();
      context = std::move(window);
    } else if (!group.offscreen || !oneOffscreenContext) {
      try {
        context = std::make_unique<EglContext>(EglContext::Options{
            .share = static_cast<const EglContext*>(group.owner), .device = gpu});
      } catch (const Error& e) {
        throw Error(concat(config_.path.string(), ":", spec.line, ": wall '", spec.name,
                           "' on GPU ", gpu, ": ", e.what()));
      }
    }
    const GlContext* drawsWith = context ? context.get() : &group.offscreen->glContext();
    // The group's first wall simulates; the others read (reader numbers 0, 1, ...).
    int shareReader = -1;
    if (group.share) {
      if (group.owner)
        shareReader = group.readers++;
      else
        group.owner = drawsWith, group.readers = 0;
    }
    if (spec.menu) menuWall_ = i;
    log::info("wall '", spec.name, "': ", drawsWith->description(),
              context ? std::string()
                      : concat(" (the context of wall '", group.offscreen->walls().front()->name(),
                               "')"));
    WallRendererSetup setup{.wall = spec,
                            .initial = main_.initialState(),
                            .terrain = terrain_,
                            .capacity = config_.run.capacity,
                            .capacityLimit = config_.run.capacityLimit,
                            .backend = config_.run.backend,
                            .share = group.share,
                            .shareReader = shareReader,
                            .tuning = config_.gpu,
                            .nearPlane = config_.run.nearPlane,
                            .farPlane = config_.run.farPlane};
    walls_.push_back(std::make_unique<RenderWall>(setup, i));
    walls_.back()->sampleFrom(statsWarmup_);
    if (context) {
      std::unique_ptr<GlContext> uploads =
          config_.gpu.uploadContext ? uploadContext(*context, spec, gpu) : nullptr;
      contexts_.push_back(std::make_unique<RenderContext>(
          std::move(context), std::vector<RenderWall*>{walls_.back().get()}, channel_, barrier_,
          std::move(uploads)));
      if (!spec.window) group.offscreen = contexts_.back().get();
    } else {
      group.offscreen->addWall(walls_.back().get());
    }
  }
  // The hooks and overlays set later reach the threads with packet 0 (FrameChannel's lock).
  for (auto& c : contexts_)
    c->start();
}

// A second context of `context`'s share group, for its upload thread (a
// series' steps copied to the GPU beside the walls' work); null, said once,
// where none can be made: the walls then copy the steps themselves.
std::unique_ptr<GlContext> AppRun::uploadContext(const GlContext& context, const WallSpec& spec,
                                                 int gpu) {
  try {
    if (spec.window) {
      GlfwWindow::Options o;
      o.title = "Sandstorm: uploads for " + spec.name;
      o.size = {1, 1};
      o.visible = false;
      o.decorated = false;
      o.vsync = false;
      o.share = static_cast<const GlfwWindow*>(&context);
      return std::make_unique<GlfwWindow>(*glfw_, o);
    }
    return std::make_unique<EglContext>(
        EglContext::Options{.share = static_cast<const EglContext*>(&context), .device = gpu});
  } catch (const Error& e) {
    log::warn("wall '", spec.name, "': no second OpenGL context for uploads (", e.what(),
              "); its thread copies a series' steps to the GPU itself, as with "
              "gpu.upload_context = false");
    return nullptr;
  }
}

void AppRun::openMenu() {
  if (!operatorWindow_ && menuWall_ < 0 && !options_.menuScript) return;
  std::unique_ptr<GlfwWindow> console;
  if (operatorWindow_)
    console = std::make_unique<GlfwWindow>(
        *glfw_, windowOptions("Sandstorm: operator", *config_.menu.operatorWindow));
  const int wallCount = int(walls_.size());
  const int shown = menuWall_ >= 0 ? menuWall_ : 0;
  // (A cluster's rank 0 may drive no wall: then only its operator window shows the menu.)
  const WallSpec wall = wallCount > 0 ? config_.walls[std::size_t(shown)] : WallSpec{};
  GLFWwindow* wallWindow = wallCount > 0 && wallWindows_[std::size_t(shown)]
                               ? wallWindows_[std::size_t(shown)]->handle()
                               : nullptr;
  std::optional<MenuScript> script;
  if (options_.menuScript) script = MenuScript::load(*options_.menuScript);
  menu_ = std::make_unique<MenuHost>(
      main_, std::move(console), wallWindow, wall.window ? wall.window->size : wall.offscreenSize,
      wall.stereo, fieldChoices(projectRoot_ / "data", projectRoot_),
      [this](const std::string& choice) {
        loadField(choice);
        if (recorder_) recorder_->recordField(main_.nextFrame(), choice);
      },
      [this](const std::string& path) {
        if (path.ends_with(".toml"))
          editor_.save(path, main_.pendingState());
        else
          editor_.bake(path, main_);
      },
      std::move(script));
  if (!operatorWindow_ && wallCount > 0)
    walls_[std::size_t(shown)]->addOverlay([this] { return menu_->latest(); }, menu_->font(),
                                           RenderWall::Layer::Menu);
}

// The legend's wall: the one marked `legend = true`, else the menu's, else the
// first. In cluster mode the configuration's walls were split among the ranks
// with the legend's wall marked (MpiCluster): the rank that drives it builds
// the legend, a rank other than 0 from the packets it receives
// (showMirrorLegend); the others show none.
void AppRun::openLegend() {
  const auto& all = config_.walls;
  auto chosen = std::find_if(all.begin(), all.end(), [](const WallSpec& w) { return w.legend; });
  if (chosen == all.end() && cluster_) return;
  if (chosen == all.end())
    chosen = std::find_if(all.begin(), all.end(), [](const WallSpec& w) { return w.menu; });
  if (chosen == all.end()) chosen = all.begin();
  if (chosen == all.end()) return;
  for (const auto& wall : walls_) {
    const WallSpec& spec = wall->setup().wall;
    if (spec.name != chosen->name) continue;
    // Laid out for one eye's image and drawn into each: a stereo wall shows
    // it to both eyes at the wall's plane, readable.
    const glm::ivec2 image = spec.window ? spec.window->size : spec.offscreenSize;
    const glm::ivec4 eye = eyeViewports(spec.stereo, image).front();
    legend_ = std::make_unique<LegendHost>(glm::ivec2(eye.z, eye.w));
    wall->addOverlay([this] { return legend_->latest(); }, legend_->font(),
                     RenderWall::Layer::Picture);
    return;
  }
}

// What colours this wall's lines at this frame, for the exported polylines.
// The wall's field outlives the call (the wall holds it until its next frame).
LineColoring AppRun::lineColoring(const WallRenderer& wall, const FramePacket& packet) {
  const ParticleState& state = wall.particles().state();
  return {.quantity = state.render.colorBy,
          .field = wall.particles().field().get(),
          .blend = packet.fieldBlend,
          .strength = state.sim.fieldStrength};
}

// The streamlines this wall draws, traced on the CPU (their twin) from its
// replica of the state and field at this frame.
void AppRun::dumpStreamlines(const WallRenderer& wall, const FramePacket& packet) {
  const ParticleState& state = wall.particles().state();
  const std::vector<Streamline> lines =
      wallStreamlines(state, wall.particles().field(), packet.fieldBlend, terrain_.get());
  std::vector<PointArray> extra;
  if (auto a = streamlineColorArray(lines, lineColoring(wall, packet)))
    extra.push_back(std::move(*a));
  writeStreamlinesVtp(lines, state.render.colorBy, *options_.dumpStreamlines, "--dump-streamlines",
                      extra);
  log::info("wrote ", lines.size(), " streamlines to ", options_.dumpStreamlines->string(),
            state.streamlines.enabled ? "" : " (streamlines.enabled is off: not drawn)");
}

// The particles' trails as polylines, each ending at its particle.
void AppRun::dumpTrails(const WallRenderer& wall, const FramePacket& packet) {
  const std::vector<Particle> particles = wall.particles().update().readBack();
  std::vector<std::size_t> owners;
  const std::vector<Streamline> lines =
      trailLines(particles, wall.particles().readBackTrails(), owners);
  const ParticleState& state = wall.particles().state();
  std::vector<PointArray> extra;
  if (auto a = trailColorArray(lines, owners, particles, lineColoring(wall, packet)))
    extra.push_back(std::move(*a));
  writeStreamlinesVtp(lines, state.render.colorBy, *options_.dumpTrails, "--dump-trails", extra);
  log::info("wrote ", lines.size(), " trails to ", options_.dumpTrails->string(),
            state.render.trailLength > 0 ? "" : " (render.trail_length is 0)");
}

void AppRun::hookWalls() {
  for (std::size_t i = 0; i < walls_.size(); ++i) {
    const bool first = i == 0;
    walls_[i]->setFrameHook([this, first, i](WallRenderer& wall, const FramePacket& packet) {
      if (options_.hashLog) hashes_.add(wall, packet.frame);
      const int f = int(packet.frame);
      const bool last = f == lastFrame_;
      if (options_.screenshotDir &&
          (last || (options_.screenshotEvery > 0 && f % options_.screenshotEvery == 0))) {
        const std::string name = last ? wall.wall().name : concat(wall.wall().name, "_", f);
        images_->write(wall.capture(), *options_.screenshotDir / (name + ".png"));
      }
      if (first && last && options_.dumpParticles) {
        const std::vector<Particle> particles = wall.particles().update().readBack();
        writeParticlesVtp(particles, *options_.dumpParticles);
        log::info("wrote ", particles.size(), " particles to ", options_.dumpParticles->string());
      }
      if (first && last && options_.dumpStreamlines) dumpStreamlines(wall, packet);
      if (first && last && options_.dumpTrails) dumpTrails(wall, packet);
      if (observer_) observer_(i, wall, packet);
      if (cluster_)
        cluster_->drawn(int(i), packet.frame);  // the main thread holds the swap for every rank
    });
    if (movie_ && movie_->shows(i))
      walls_[i]->setPictureHook(
          [this, i](WallRenderer& wall, const FramePacket& packet) {
            movie_->add(i, packet.frame, wall.captureEyes());
          },
          options_.movie->menu);
  }
}

void AppRun::loadField(const std::string& choice) {
  const FieldSpec spec = fieldSpecFor(choice, config_.field);
  useField(main_, makeField(spec, projectRoot_));
  editor_.setFieldSpec(spec);
}

void AppRun::track(float dt) {
  const std::uint32_t frame = main_.nextFrame();
  // A replayed session's field switches, at their frames.
  while (replayFieldAt_ < replay_.fields.size() && replay_.fields[replayFieldAt_].frame <= frame)
    loadField(replay_.fields[replayFieldAt_++].source);
  streamField();
  // A replayed session's navigation, when it recorded one.
  while (replayNavigationAt_ < replay_.navigation.size() &&
         replay_.navigation[replayNavigationAt_].frame <= frame)
    navigation_ = replay_.navigation[replayNavigationAt_++].navigation;
  TrackingSample sample;
  WandRay ray;
  if (tracking_) {
    sample = tracking_->sample(frame);
    const ParticleState state = main_.pendingState();
    const WandScene scene{
        .state = &state, .navigation = navigation_, .ground = terrain_.get(), .menu = menuTarget()};
    WandActions actions = tracking_->wand(sample, scene, dt);
    ray = actions.ray;
    if (!tracking_->replaying()) {
      if (actions.menu && menu_) menu_->pointWand(actions.menu->pixel, actions.menu->down);
      for (const auto& [key, value] : actions.sets) {
        try {
          main_.set(key, value);
        } catch (const Error& e) {
          log::warn("wand: ", e.what());
        }
      }
      if (actions.navigation) navigation_ = *actions.navigation;
    }
  }
  HeadPose head = head_->pose(main_.time());
  if (sample.active && sample.headTracked) {
    head.position = sample.head.position;
    head.right = sample.head.right();
  }
  main_.setTracking(sample, ray);
  main_.setViewer(Viewer{head, navigation_});
  if (recorder_) {
    if (sample.active) recorder_->recordTracking(frame, sample);
    recorder_->recordNavigation(frame, navigation_);
  }
}

std::optional<WandMenuTarget> AppRun::menuTarget() const {
  if (!menu_ || menuWall_ < 0) return std::nullopt;
  const WallSpec& wall = config_.walls[std::size_t(menuWall_)];
  const MenuPanel::Rect panel = menu_->panelRect();
  return WandMenuTarget{wall, wall.window ? wall.window->size : wall.offscreenSize, panel.min,
                        panel.max};
}

void AppRun::showMenu(float dt, const std::vector<std::string>& probe) {
  MenuStats stats;
  stats.frame = main_.nextFrame();
  for (const auto& w : walls_) {
    const WallStats s = w->stats();
    stats.walls.push_back({w->name(), s.fps, s.frameMs, s.updateMs, s.renderMs, s.postMs,
                           s.fieldUploadMs, s.liveParticles, s.capacity, s.liveMolecules});
  }
  if (tracking_) {
    const TrackingStatus t = tracking_->status();
    stats.tracking = MenuTrackingStats{.source = t.source,
                                       .received = t.stats.received,
                                       .dropped = t.stats.dropped,
                                       .foreign = t.stats.foreign,
                                       .waiting = t.waiting,
                                       .lost = t.lost,
                                       .trackerFrame = t.trackerFrame,
                                       .lastError = t.stats.lastError,
                                       .wandTracked = t.wandTracked,
                                       .wandPresent = t.wandPresent};
  }
  stats.probe = probe;
  menu_->frame(main_.nextFrame(), dt, stats);
}

// The main thread's work before it makes a frame's packet.
void AppRun::beforePacket(float dt) {
  track(dt);
  chooseSolverDevice();
  const ParticleState state = main_.pendingState();
  autoColorRange(state);
  const auto field = main_.field();
  const std::vector<std::string> probe = probeLines(state, field.get(), lastPacket_.get());
  if (menu_) showMenu(dt, probe);
  if (legend_) legend_->frame(dt, state, field.get(), probe);
}

// solver.device = auto: the GPU, unless a wall's OpenGL runs in software
// (llvmpipe), where the main context's threads solve faster than the
// emulated GPU. The walls' contexts decide it, so every run of a
// configuration on a machine chooses alike, at the same frame; a replayed
// session holds the choice it recorded.
void AppRun::chooseSolverDevice() {
  if (options_.replay || main_.pendingState().solver.device != FluidDevice::Auto) return;
  bool software = false;
  for (auto& c : contexts_)
    software = software || softwareRenderer(c->glContext().description());
  main_.set("solver.device", std::string(software ? "cpu" : "gpu"));
  log::info(
      "solver.device = auto: ",
      software ? "cpu (the walls' OpenGL runs in software, slower than the CPU's threads)" : "gpu");
}

// render.color_range = particles: every render.color_every frames, the first
// wall's newest measurement of its particles becomes render.color_min/max, a
// change like a user's (every wall applies it at one frame; sessions record it).
void AppRun::autoColorRange(const ParticleState& state) {
  if (state.render.colorRange != ColorRange::Particles || walls_.empty() || options_.replay) return;
  if (main_.nextFrame() < nextColorRangeAt_) return;
  const std::optional<ParticleMeasurement> m = walls_[0]->stats().measure;
  if (!m || m->live == 0 || (colorRangeFrom_ && m->frame <= *colorRangeFrom_)) return;
  colorRangeFrom_ = m->frame;
  nextColorRangeAt_ = main_.nextFrame() + std::uint32_t(std::max(state.render.colorEvery, 1));
  float low = m->least, high = m->greatest;
  if (!(high > low)) {  // one value: a range around it
    const float pad = std::max(std::abs(low) * 1e-3f, 1e-6f);
    low -= pad;
    high += pad;
  }
  if (low == state.render.colorMin && high == state.render.colorMax) return;
  main_.set("render.color_min", low);
  main_.set("render.color_max", high);
}

// A right click on a wall's window places the probe (probe.position, a change
// like a menu edit) where the ray through that pixel meets the slice, or
// nearest the field's centre.
std::optional<WorldRay> AppRun::rayThrough(const DesktopInput::Click& click) const {
  if (click.window >= windows_.size()) return std::nullopt;
  const auto it = std::find(wallWindows_.begin(), wallWindows_.end(), windows_[click.window]);
  if (it == wallWindows_.end()) return std::nullopt;
  const WallSpec& wall = config_.walls[std::size_t(it - wallWindows_.begin())];
  const glm::ivec2 size = glm::max(windows_[click.window]->framebufferSize(), glm::ivec2(1));
  const Viewer viewer =
      lastPacket_ ? lastPacket_->viewer : Viewer{head_->pose(main_.time()), navigation_};
  return wallClickRay(wall, viewer, click.at, float(size.x) / float(size.y), config_.run.nearPlane,
                      config_.run.farPlane);
}

void AppRun::pickProbe() {
  const std::optional<DesktopInput::Click> click = input_->takeClick();
  if (!click) return;
  const ParticleState state = main_.pendingState();
  if (!state.probe.enabled) {
    log::info("right click: the probe is off; turn on probe.enabled to place it");
    return;
  }
  const std::optional<WorldRay> ray = rayThrough(*click);
  if (!ray) return;
  try {
    main_.set("probe.position",
              pickProbePoint(state, ray->origin, ray->direction, fieldCentre(*ray)));
  } catch (const Error& e) {
    log::warn("probe: ", e.what());
  }
}

void AppRun::streamField() {
  const std::uint32_t frame = main_.nextFrame();
  if (fieldStream_)
    for (FieldStream::Step& s : fieldStream_->take())
      appendFieldStep(s.time, s.file.string(), std::move(s.field), s.completeAt);
  while (replayStepAt_ < replay_.fieldSteps.size() &&
         replay_.fieldSteps[replayStepAt_].frame <= frame) {
    const ScheduledFieldStep& s = replay_.fieldSteps[replayStepAt_++];
    try {
      appendFieldStep(s.time, s.file, FieldStream::load(s.file, field_.streamOptions), frame);
    } catch (const Error& e) {
      log::warn("field stream: the replayed step ", s.file, " was skipped: ", e.what());
    }
  }
}

void AppRun::appendFieldStep(double time, const std::string& file,
                             std::shared_ptr<const VectorField> field, std::uint32_t completeAt) {
  const std::uint32_t frame = main_.nextFrame();
  try {
    main_.appendFieldFrame(time, std::move(field), file);
  } catch (const Error& e) {
    log::warn("field stream: the step at t = ", time, " s (", file, ") was skipped: ", e.what(),
              "; the last good field stays");
    return;
  }
  log::info("field: the step at t = ", time, " s (", file, ") joins the field at frame ", frame,
            " (found complete during frame ", completeAt, "; ", main_.fieldFrames(), " steps now)");
  if (recorder_) recorder_->recordFieldStep(frame, time, file);
}

// A left drag that began on an obstacle moves it (ObstacleDrag); one that
// began a push moves the push (MoleculePush).
void AppRun::dragObstacle(float dt) {
  const std::optional<DesktopInput::Drag> drag = input_->takeDrag();
  if (!drag) return;
  const std::optional<WorldRay> ray = rayThrough(drag->at);
  if (ray) {
    obstacleDrag_.drag(main_, *ray, dt, drag->released);
    moleculePush_.drag(main_, *ray, fieldCentre(*ray), drag->released);
  } else if (drag->released) {
    obstacleDrag_.drag(main_, WorldRay{}, dt, true);
    moleculePush_.drag(main_, WorldRay{}, glm::vec3(0.0f), true);
  }
}

// The field's centre in the room, or a metre along the ray without a field.
glm::vec3 AppRun::fieldCentre(const WorldRay& ray) const {
  const auto field = main_.field();
  return field && field->field ? field->placement.toRoom(field->field->bounds().center())
                               : ray.origin + ray.direction;
}

// A rank other than 0 shows its own legend (when one of its walls is the
// legend's, or its first wall) from the packets it receives.
void AppRun::showMirrorLegend(float dt, std::shared_ptr<const FramePacket> packet) {
  if (!legend_) return;
  if (!mirror_) mirror_ = std::make_unique<StateMirror>(main_.initialState());
  mirror_->apply(std::move(packet));
  const auto field = mirror_->field();
  legend_->frame(dt, mirror_->state(), field.get(),
                 probeLines(mirror_->state(), field.get(), mirror_->last()));
}

// What the probe reads: the field there (the main context's current field
// frame) and the first wall's count of particles near it, a few frames old.
std::vector<std::string> AppRun::probeLines(const ParticleState& state, const FieldUpdate* field,
                                            const FramePacket* last) const {
  if (!state.probe.enabled) return {};
  const auto point = probePoint(state, last ? last->wand : WandRay{},
                                last ? last->viewer.navigation : navigation_);
  if (!point) return {};
  PhysicsInputs in;
  in.field = field ? field->field.get() : nullptr;
  in.sparse = field ? field->sparse.get() : nullptr;
  in.placement = field ? field->placement : FieldPlacement{};
  in.settings = state.sim;
  in.obstacles = collisionShapes(state, terrain_.get());
  const ProbeReading r = readProbe(*point, in);
  std::vector<std::string> lines;
  char text[160];
  std::snprintf(text, sizeof text, "probe at (%.2f, %.2f, %.2f) m", r.point.x, r.point.y,
                r.point.z);
  lines.push_back(text);
  if (r.inside) {
    std::snprintf(text, sizeof text, "velocity (%.3g, %.3g, %.3g) m/s, speed %.3g m/s",
                  r.velocity.x, r.velocity.y, r.velocity.z, r.speed);
  } else {
    std::snprintf(text, sizeof text, "outside the field");
  }
  lines.push_back(text);
  for (const auto& [name, value] : r.scalars) {
    std::snprintf(text, sizeof text, "%.60s %.4g", name.c_str(), value);
    lines.push_back(text);
  }
  if (!walls_.empty())
    if (const std::optional<ParticleMeasurement> m = walls_[0]->stats().measure) {
      std::snprintf(text, sizeof text, "%u particle%s within %.2f m (frame %u)", m->nearProbe,
                    m->nearProbe == 1 ? "" : "s", state.probe.radius, m->frame);
      lines.push_back(text);
    }
  return lines;
}

void AppRun::reportProgress(Clock::time_point now) {
  if (now - lastReport_ <= std::chrono::seconds(2) || walls_.empty()) return;
  lastReport_ = now;
  const WallStats s = walls_[0]->stats();
  log::info("frame ", s.frame, lastFrame_ >= 0 ? concat("/", lastFrame_ + 1) : std::string(), ": ",
            s.liveParticles, " particles, ", s.frameMs, " ms per frame on '", walls_[0]->name(),
            "'", tracking_ && tracking_->status().lost ? "; tracking lost" : "");
}

void AppRun::meterPlayback(Clock::time_point now) {
  if (field_.series) playback_.frame(std::uint32_t(frames_), main_.fieldStatus(), now);
}

bool AppRun::advance() {
  if (interrupted || (lastFrame_ >= 0 && frames_ > lastFrame_)) return false;
  if (frames_ == 0) log::info("the walls are ready: frames begin");
  const auto now = Clock::now();
  const float dt = std::chrono::duration<float>(now - lastTick_).count();
  lastTick_ = now;
  if (glfw_) {
    GlfwLibrary::pollEvents();
    if (menu_ && menu_->scriptCloses(main_.nextFrame()) && !windows_.empty())
      windows_.front()->requestClose();
    bool close = menu_ && menu_->operatorWindowClosed();
    for (GlfwWindow* w : windows_)
      close = close || w->shouldClose();
    if (close) return false;
    input_->update(dt, dynamic_cast<DesktopHead*>(head_.get()), navigation_,
                   menu_ && menu_->wantsMouse(), false);
    pickProbe();
    dragObstacle(dt);
  }
  for (const auto& w : walls_)
    failed_ = failed_ || w->error().has_value();
  if (recorder_ && recorder_->error()) {
    log::error(*recorder_->error());
    failed_ = true;
  }
  if (failed_) return false;
  beforePacket(dt);
  lastPacket_ = std::make_shared<const FramePacket>(main_.next());
  if (!channel_.publish(lastPacket_)) return false;
  helicopter_.update(main_);
  editor_.update(main_);
  fluid_.update(main_, *lastPacket_);
  if (!options_.replay) obstaclePaths_.update(main_, *lastPacket_);
  meterPlayback(Clock::now());
  ++frames_;
  reportProgress(now);
  pacer_.wait();
  return true;
}

void AppRun::runCluster() {
  // Rank 0 makes and broadcasts each packet, the other ranks receive it. Frame
  // f's packet travels while the walls draw frame f - 1; then swap() waits for
  // this rank's walls and every other rank, and only then do the walls present
  // f - 1. Stop requests travel with the swap, so every rank stops at the same frame.
  cluster_->watchInterrupt(&interrupted);
  log::info("the walls are ready: frames begin");
  for (;;) {
    const auto now = Clock::now();
    const float dt = std::chrono::duration<float>(now - lastTick_).count();
    lastTick_ = now;
    int stop = interrupted ? ClusterLink::kInterrupted : 0;
    if (cluster_->root() && menu_ && menu_->scriptCloses(main_.nextFrame()))
      stop |= ClusterLink::kClosed;
    if (glfw_) {
      GlfwLibrary::pollEvents();
      bool close = menu_ && menu_->operatorWindowClosed();
      for (GlfwWindow* w : windows_)
        close = close || w->shouldClose();
      if (close) stop |= ClusterLink::kClosed;
      if (cluster_->root()) {
        input_->update(dt, dynamic_cast<DesktopHead*>(head_.get()), navigation_,
                       menu_ && menu_->wantsMouse(), false);
        pickProbe();
        dragObstacle(dt);
      }
    }
    std::shared_ptr<const FramePacket> packet;
    if (!cluster_->root()) {
      packet = cluster_->receive();  // null: rank 0 sent the last frame
      if (packet) showMirrorLegend(dt, packet);
    } else if (lastFrame_ < 0 || frames_ <= lastFrame_) {
      beforePacket(dt);
      packet = std::make_shared<const FramePacket>(main_.next());
      lastPacket_ = packet;
      cluster_->send(*packet);
      helicopter_.update(main_);
      editor_.update(main_);
      fluid_.update(main_, *packet);
      if (!options_.replay) obstaclePaths_.update(main_, *packet);
      meterPlayback(Clock::now());
    } else {
      cluster_->sendStop();
    }
    if (packet) channel_.publish(packet);
    if (frames_ > 0) {
      const ClusterLink::Verdict verdict = cluster_->swap(std::uint32_t(frames_ - 1), stop, [&] {
        return std::any_of(walls_.begin(), walls_.end(),
                           [](const auto& w) { return w->error().has_value(); });
      });
      failed_ = failed_ || verdict.failed;
      if (!verdict.go) break;
      barrier_.arrive_and_wait();  // every rank drew frame f - 1: present it
    }
    if (!packet) break;
    ++frames_;
    reportProgress(now);
    if (cluster_->root()) pacer_.wait();  // the others wait for its packets
  }
  barrier_.arrive_and_drop();  // walls finish what was published without the main thread
}

int AppRun::finish() {
  if (interrupted)
    log::info("interrupted: stopped every wall cleanly");
  else if (lastFrame_ < 0 || frames_ <= lastFrame_)
    log::info("a window closed: stopped every wall cleanly");
  if (images_)
    for (const std::string& failure : images_->finish()) {
      log::error(failure);
      failed_ = true;
    }
  if (cluster_) cluster_->finish();
  if (movie_ && !movie_->finish()) failed_ = true;
  if (options_.hashLog) hashes_.write(*options_.hashLog);
  if (!cluster_ || cluster_->root()) {
    try {
      if (options_.saveField) editor_.save(*options_.saveField, main_.state());
      if (options_.bakeField) editor_.bake(*options_.bakeField, main_);
    } catch (const Error& e) {
      log::error(e.what());
      failed_ = true;
    }
  }

  const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
  for (const auto& w : walls_)
    failed_ = failed_ || w->error().has_value();
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  log::info("stats: ", frames_, " frames in ", seconds, " s (", frames_ / std::max(seconds, 1e-9),
            " frames/s), ", walls_.size(), " wall(s); peak memory ",
            formatByteSize(double(usage.ru_maxrss) * 1024.0), " resident");
  for (const auto& w : walls_) {
    const WallStats s = w->stats();
    // The count is read back late, so that the frame loop never waits for it.
    log::info("  wall '", w->name(), "': ", s.liveParticles,
              " live particles a frame or two before its last (", s.frame, "); last frame ",
              s.frameMs, " ms; ", s.fieldUploads, " field upload(s) taking ", s.fieldUploadTotalMs,
              " ms in all, the last ", s.fieldUploadMs, " ms; ", s.glErrors, " GL error(s)",
              w->error() ? " FAILED: " + *w->error() : std::string());
  }
  if (tracking_) {
    const TrackingStatus t = tracking_->status();
    log::info("  tracking (", t.source, "): ", t.stats.received, " frames received, ",
              t.stats.dropped, " dropped, ", t.stats.foreign, " from other hosts dropped",
              t.waiting ? ", none measured" : (t.lost ? ", lost at the end" : ""),
              t.stats.lastError.empty() ? std::string() : "; last refused: " + t.stats.lastError);
  }
  if (field_.series) {
    // What reading the series cost, against what playback needed.
    const SeriesReader::Stats r = field_.series->stats();
    const FieldPlaybackStatus p = main_.fieldStatus();
    log::info("  field series: ", r.stepsRead, " step(s) read from disk, ",
              formatByteSize(r.bytesRead), " at ",
              formatByteSize(r.bytesRead / std::max(r.secondsReading, 1e-9)),
              "/s a reader; playback waited ", p.framesWaited, " frame(s) for steps",
              p.error.empty() ? std::string() : "; stopped: " + p.error);
  }
  std::vector<WallRunStats> measured;
  for (const auto& w : walls_)
    measured.push_back(summarize(w->name(), w->renderer(), w->samples(), w->measuredFrames(),
                                 w->stats().liveParticles));
  RunStats stats = summarize(statsWarmup_, std::move(measured));
  stats.playback = playback_.stats();
  if (tracking_) {
    const TrackerStats t = tracking_->status().stats;
    stats.tracking = TrackingRunStats{t.received, t.dropped, t.foreign};
  }
  logRunStats(stats);
  if (options_.stats) {
    writeRunStats(stats, *options_.stats);
    log::info("run statistics in ", options_.stats->string());
  }
  if (options_.screenshotDir) log::info("images in ", options_.screenshotDir->string(), "/");
  return failed_ ? 1 : 0;
}

}  // namespace sandstorm
