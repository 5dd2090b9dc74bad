#include "app/app.h"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <mutex>

#include "app/cluster/cluster_link.h"
#include "app/desktop_input.h"
#include "app/helicopter_controller.h"
#include "app/menu/menu_host.h"
#include "app/scene_setup.h"
#include "contexts/particles/simulation_share.h"
#include "contexts/platform/egl_context.h"
#include "contexts/platform/glfw_window.h"
#include "contexts/render/render_context.h"
#include "core/cave/viewer.h"
#include "core/sim/attribute_table.h"
#include "core/sim/main_context.h"
#include "core/sim/particle_dump.h"
#include "core/sim/session_log.h"
#include "core/util/error.h"
#include "core/util/hash.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

std::atomic<bool> interrupted{false};

void onInterrupt(int) {
  interrupted = true;
}

bool haveDisplay() {
  const char* x = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (wayland && *wayland);
}

constexpr int kHeadlessFrames = 240;

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

// Per frame and wall: "frame wall particles buffer-hash state-hash".
class HashLog {
 public:
  void add(const WallRenderer& wall, std::uint32_t frame) {
    const std::vector<Particle> particles = wall.particles().update().readBack();
    const std::string state = AttributeTable::instance().describe(wall.particles().state());
    const std::string line = concat(frame, " ", wall.wall().name, " ", particles.size(), " ",
                                    std::hex, hashOf(std::span<const Particle>(particles)), " ",
                                    hashOf(std::span<const char>(state)));
    std::lock_guard lock(mutex_);
    lines_.push_back(line);
  }
  void write(const std::filesystem::path& path) {
    std::sort(lines_.begin(), lines_.end(), [](const std::string& a, const std::string& b) {
      return std::stoul(a) != std::stoul(b) ? std::stoul(a) < std::stoul(b) : a < b;
    });
    std::ofstream out(path);
    for (const std::string& line : lines_)
      out << line << "\n";
    if (!out) throw Error(concat("--hash-log: cannot write ", path.string()));
  }

 private:
  std::mutex mutex_;
  std::vector<std::string> lines_;
};

}  // namespace

void applySets(AppConfig& config, const std::vector<std::string>& sets) {
  const AttributeTable& table = AttributeTable::instance();
  for (const std::string& set : sets) {
    const std::size_t eq = set.find('=');
    if (eq == std::string::npos || eq == 0)
      throw Error(concat("--set '", set, "': expected key=value, e.g. --set emitter.0.rate=50000"));
    const std::string key = set.substr(0, eq);
    const AttributeResult r =
        table.set(config.particles, key, table.parse(key, set.substr(eq + 1)));
    if (!r.warning.empty()) log::warn("--set ", r.warning);
  }
}

App::App(AppConfig config, AppOptions options, ClusterLink* cluster)
    : config_(std::move(config)), options_(std::move(options)), cluster_(cluster) {
  headless_ = options_.headless || !haveDisplay();
  if (headless_) {
    if (config_.anyWindow() && !options_.headless)
      log::info("no display: rendering the windows offscreen instead");
    for (WallSpec& w : config_.walls) {
      if (w.window) w.offscreenSize = w.window->size;
      w.window.reset();
      if (w.stereo == StereoMode::QuadBuffer) w.stereo = StereoMode::SideBySide;
    }
  }
  const bool offscreenOnly = !config_.anyWindow();
  if (options_.frames) config_.run.frames = *options_.frames;
  if (offscreenOnly && config_.run.frames == 0) config_.run.frames = kHeadlessFrames;
  if (offscreenOnly && !options_.screenshotDir) options_.screenshotDir = "out";
  if (offscreenOnly && config_.run.fixedDt == 0.0f) config_.run.fixedDt = 1.0f / 60.0f;
  applySets(config_, options_.sets);
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
  // Offscreen there is nobody to use the menu: it only shows when a script drives it.
  if (headless_ && !options_.menuScript) options_.noMenu = true;
  if (options_.noMenu) {
    config_.menu.operatorWindow.reset();
    for (WallSpec& w : config_.walls)
      w.menu = false;
  }
}

int App::run() {
  if (cluster_) cluster_->localize(config_, options_);  // this rank's walls and outputs
  const std::filesystem::path configDir = config_.path.parent_path();
  // In cluster mode only rank 0 makes the field (unless every rank reads it): it travels in
  // packets.
  const FieldSource field =
      !cluster_ || cluster_->makesField() ? makeField(config_.field, configDir) : FieldSource{};
  const std::shared_ptr<const HeightMap> terrain = makeTerrain(config_.scene, configDir);
  if (options_.screenshotDir) std::filesystem::create_directories(*options_.screenshotDir);

  MainContext::Options mainOptions;
  mainOptions.seed = config_.run.seed;
  mainOptions.fixedDt = config_.run.fixedDt;
  mainOptions.capacityLimit = config_.run.capacityLimit;
  MainContext main(config_.particles, field.update, mainOptions);
  if (field.timeline) useField(main, field);
  std::unique_ptr<SessionRecorder> recorder;
  if (options_.record) {
    recorder = std::make_unique<SessionRecorder>(*options_.record);
    main.setChangeListener(
        [&](std::uint32_t frame, const StateChange& c) { recorder->record(frame, c); });
  }
  if (options_.replay)
    for (const ScheduledChange& s : readSessionLog(*options_.replay))
      main.schedule(s.frame, s.change);
  HelicopterController helicopter(terrain);
  if (!cluster_ || cluster_->root())
    helicopter.update(main);  // the configured helicopter's field and dust, before packet 0
  std::unique_ptr<HeadTracker> head = makeHeadTracker(config_.head);
  Navigation navigation = Navigation::from(config_.navigation);

  // Contexts are made here (GLFW wants windows on the main thread), then each
  // wall's thread makes its own current.
  std::unique_ptr<GlfwLibrary> glfw;
  const bool operatorWindow = config_.menu.operatorWindow && !headless_;
  if (config_.anyWindow() || operatorWindow) {
    glfw = std::make_unique<GlfwLibrary>();
    // Every window's monitor exists, or nothing starts.
    const int monitors = glfw->monitorCount();
    for (std::size_t i = 0; i < config_.walls.size(); ++i) {
      const WallSpec& w = config_.walls[i];
      if (w.window && w.window->monitor >= std::max(monitors, 1))
        throw Error(concat(config_.path.string(), ":", w.line, ": wall[", i,
                           "].window.monitor: monitor ", w.window->monitor, " does not exist; ",
                           monitors, " connected"));
    }
  }
  const int wallCount = int(config_.walls.size());
  FrameChannel channel(wallCount);
  // Cluster mode: the main thread joins the swap barrier, to hold the walls until every rank drew.
  RenderContext::SwapBarrier barrier(wallCount + (cluster_ ? 1 : 0));
  std::vector<std::unique_ptr<RenderContext>> walls;
  std::vector<GlfwWindow*> windows;
  std::vector<GlfwWindow*> wallWindows(std::size_t(wallCount), nullptr);
  int menuWall = -1;
  // One simulation per GPU: windows share objects with the first window, offscreen
  // walls with the first offscreen wall (GLX and EGL contexts cannot share).
  struct ShareGroup {
    const GlContext* owner = nullptr;
    std::shared_ptr<SimulationShare> share;
    int readers = 0;
  };
  ShareGroup windowGroup, offscreenGroup;
  if (config_.run.sharedSimulation) {
    for (const WallSpec& w : config_.walls)
      ++(w.window ? windowGroup : offscreenGroup).readers;
    for (ShareGroup* g : {&windowGroup, &offscreenGroup})
      if (g->readers-- > 0) g->share = std::make_shared<SimulationShare>(g->readers);
  }
  for (int i = 0; i < wallCount; ++i) {
    const WallSpec& spec = config_.walls[std::size_t(i)];
    ShareGroup& group = spec.window ? windowGroup : offscreenGroup;
    std::unique_ptr<GlContext> context;
    if (spec.window) {
      GlfwWindow::Options o = windowOptions("Sandstorm: " + spec.name, *spec.window);
      o.quadBufferStereo = spec.stereo == StereoMode::QuadBuffer;
      o.share = static_cast<const GlfwWindow*>(group.owner);
      auto window = std::make_unique<GlfwWindow>(*glfw, o);
      windows.push_back(window.get());
      wallWindows[std::size_t(i)] = window.get();
      context = std::move(window);
    } else {
      context = std::make_unique<EglContext>(
          EglContext::Options{.share = static_cast<const EglContext*>(group.owner)});
    }
    // The group's first wall simulates; the others read (reader numbers 0, 1, ...).
    int shareReader = -1;
    if (group.share) {
      if (group.owner)
        shareReader = group.readers++;
      else
        group.owner = context.get(), group.readers = 0;
    }
    if (spec.menu) menuWall = i;
    log::info("wall '", spec.name, "': ", context->description());
    WallRendererSetup setup{.wall = spec,
                            .initial = main.initialState(),
                            .terrain = terrain,
                            .capacity = config_.run.capacity,
                            .capacityLimit = config_.run.capacityLimit,
                            .backend = config_.run.backend,
                            .share = group.share,
                            .shareReader = shareReader,
                            .nearPlane = config_.run.nearPlane,
                            .farPlane = config_.run.farPlane};
    walls.push_back(
        std::make_unique<RenderContext>(std::move(context), setup, channel, i, barrier));
  }

  std::vector<GLFWwindow*> inputWindows;
  for (GlfwWindow* w : windows)
    inputWindows.push_back(w->handle());
  DesktopInput input(inputWindows);
  DesktopHead* desktopHead = dynamic_cast<DesktopHead*>(head.get());

  std::unique_ptr<MenuHost> menu;
  if (operatorWindow || menuWall >= 0 || options_.menuScript) {
    std::unique_ptr<GlfwWindow> console;
    if (operatorWindow)
      console = std::make_unique<GlfwWindow>(
          *glfw, windowOptions("Sandstorm: operator", *config_.menu.operatorWindow));
    const int shown = menuWall >= 0 ? menuWall : 0;
    // (A cluster's rank 0 may drive no wall: then only its operator window shows the menu.)
    const WallSpec wall = wallCount > 0 ? config_.walls[std::size_t(shown)] : WallSpec{};
    GLFWwindow* wallWindow = wallCount > 0 && wallWindows[std::size_t(shown)]
                                 ? wallWindows[std::size_t(shown)]->handle()
                                 : nullptr;
    std::optional<MenuScript> script;
    if (options_.menuScript) script = MenuScript::load(*options_.menuScript);
    // The project's data/ sits beside config/.
    const std::filesystem::path root = std::filesystem::absolute(configDir).parent_path();
    menu = std::make_unique<MenuHost>(
        main, std::move(console), wallWindow, wall.window ? wall.window->size : wall.offscreenSize,
        fieldChoices(root / "data", root),
        [&main, root, this](const std::string& choice) {
          useField(main, makeField(fieldSpecFor(choice, config_.field), root));
        },
        std::move(script));
    if (!operatorWindow && wallCount > 0)
      walls[std::size_t(shown)]->setOverlay([&menu] { return menu->latest(); }, menu->font());
  }

  if (cluster_) {
    if (!cluster_->ready("")) return 1;  // some rank could not open its walls; rank 0 said why
    cluster_->shareField(field);
  }

  const int lastFrame = config_.run.frames > 0 ? config_.run.frames - 1 : -1;
  HashLog hashes;
  for (std::size_t i = 0; i < walls.size(); ++i) {
    const bool first = i == 0;
    walls[i]->setFrameHook([&, this, lastFrame, first, i](WallRenderer& wall,
                                                          const FramePacket& packet) {
      if (options_.hashLog) hashes.add(wall, packet.frame);
      const int f = int(packet.frame);
      const bool last = f == lastFrame;
      if (options_.screenshotDir &&
          (last || (options_.screenshotEvery > 0 && f % options_.screenshotEvery == 0))) {
        const std::string name = last ? wall.wall().name : concat(wall.wall().name, "_", f);
        writePng(wall.capture(), *options_.screenshotDir / (name + ".png"));
      }
      if (first && last && options_.dumpParticles) {
        const std::vector<Particle> particles = wall.particles().update().readBack();
        writeParticlesVtp(particles, *options_.dumpParticles);
        log::info("wrote ", particles.size(), " particles to ", options_.dumpParticles->string());
      }
      if (cluster_)
        cluster_->drawn(int(i), packet.frame);  // the main thread holds the swap for every rank
    });
    walls[i]->start();
  }

  interrupted = false;
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
  const auto start = std::chrono::steady_clock::now();
  auto lastReport = start, lastTick = start;
  int frames = 0;
  bool failed = false;
  const auto showMenu = [&](float dt) {
    MenuStats stats;
    stats.frame = main.nextFrame();
    for (const auto& w : walls) {
      const WallStats s = w->stats();
      stats.walls.push_back({w->name(), s.fps, s.frameMs, s.updateMs, s.renderMs, s.postMs,
                             s.fieldUploadMs, s.liveParticles, s.capacity});
    }
    menu->frame(main.nextFrame(), dt, stats);
  };
  const auto reportProgress = [&](std::chrono::steady_clock::time_point now) {
    if (now - lastReport <= std::chrono::seconds(2) || walls.empty()) return;
    lastReport = now;
    const WallStats s = walls[0]->stats();
    log::info("frame ", s.frame, lastFrame >= 0 ? concat("/", lastFrame + 1) : std::string(), ": ",
              s.liveParticles, " particles, ", s.frameMs, " ms per frame on '", walls[0]->name(),
              "'");
  };
  if (cluster_) {
    // Cluster mode: rank 0 makes and broadcasts each packet, the other ranks
    // receive it. Frame f's packet travels while the walls draw frame f - 1;
    // then swap() waits for this rank's walls and every other rank, and only
    // then do the walls present f - 1. Stop requests travel with the swap, so
    // every rank stops at the same frame.
    cluster_->watchInterrupt(&interrupted);
    for (;;) {
      const auto now = std::chrono::steady_clock::now();
      const float dt = std::chrono::duration<float>(now - lastTick).count();
      lastTick = now;
      int stop = interrupted ? ClusterLink::kInterrupted : 0;
      if (cluster_->root() && menu && menu->scriptCloses(main.nextFrame()))
        stop |= ClusterLink::kClosed;
      if (glfw) {
        GlfwLibrary::pollEvents();
        bool close = menu && menu->operatorWindowClosed();
        for (GlfwWindow* w : windows)
          close = close || w->shouldClose();
        if (close) stop |= ClusterLink::kClosed;
        if (cluster_->root())
          input.update(dt, desktopHead, navigation, menu && menu->wantsMouse(), false);
      }
      std::shared_ptr<const FramePacket> packet;
      if (!cluster_->root()) {
        packet = cluster_->receive();  // null: rank 0 sent the last frame
      } else if (lastFrame < 0 || frames <= lastFrame) {
        if (menu) showMenu(dt);
        main.setViewer(Viewer{head->pose(main.time()), navigation});
        packet = std::make_shared<const FramePacket>(main.next());
        cluster_->send(*packet);
        helicopter.update(main);
      } else {
        cluster_->sendStop();
      }
      if (packet) channel.publish(packet);
      if (frames > 0) {
        const ClusterLink::Verdict verdict = cluster_->swap(std::uint32_t(frames - 1), stop, [&] {
          return std::any_of(walls.begin(), walls.end(),
                             [](const auto& w) { return w->error().has_value(); });
        });
        failed = failed || verdict.failed;
        if (!verdict.go) break;
        barrier.arrive_and_wait();  // every rank drew frame f - 1: present it
      }
      if (!packet) break;
      ++frames;
      reportProgress(now);
    }
    barrier.arrive_and_drop();  // walls finish what was published without the main thread
  } else
    while (!interrupted && (lastFrame < 0 || frames <= lastFrame)) {
      const auto now = std::chrono::steady_clock::now();
      const float dt = std::chrono::duration<float>(now - lastTick).count();
      lastTick = now;
      if (glfw) {
        GlfwLibrary::pollEvents();
        if (menu && menu->scriptCloses(main.nextFrame()) && !windows.empty())
          windows.front()->requestClose();
        bool close = menu && menu->operatorWindowClosed();
        for (GlfwWindow* w : windows)
          close = close || w->shouldClose();
        if (close) break;
        input.update(dt, desktopHead, navigation, menu && menu->wantsMouse(), false);
      }
      for (const auto& w : walls)
        failed = failed || w->error().has_value();
      if (failed) break;
      if (menu) showMenu(dt);
      main.setViewer(Viewer{head->pose(main.time()), navigation});
      if (!channel.publish(std::make_shared<const FramePacket>(main.next()))) break;
      helicopter.update(main);
      ++frames;
      reportProgress(now);
    }
  channel.close();
  for (auto& w : walls)
    w->join();
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  if (interrupted)
    log::info("interrupted: stopped every wall cleanly");
  else if (lastFrame < 0 || frames <= lastFrame)
    log::info("a window closed: stopped every wall cleanly");
  if (cluster_) cluster_->finish();
  if (options_.hashLog) hashes.write(*options_.hashLog);

  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const auto& w : walls)
    failed = failed || w->error().has_value();
  log::info("stats: ", frames, " frames in ", seconds, " s (", frames / std::max(seconds, 1e-9),
            " frames/s), ", walls.size(), " wall(s)");
  for (const auto& w : walls) {
    const WallStats s = w->stats();
    log::info("  wall '", w->name(), "': ", s.liveParticles, " live particles at frame ", s.frame,
              ", last frame ", s.frameMs, " ms; ", s.fieldUploads, " field upload(s), the last ",
              s.fieldUploadMs, " ms", w->error() ? " FAILED: " + *w->error() : std::string());
  }
  if (options_.screenshotDir) log::info("images in ", options_.screenshotDir->string(), "/");
  walls.clear();  // before the windows' library goes
  menu.reset();
  return failed ? 1 : 0;
}

}  // namespace sandstorm
