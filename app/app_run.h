// AppRun: one run of the application, from the configuration to the exit
// code. It makes, in order, the main context (terrain, recorder and replay,
// head and navigation), the walls (a GL context and a thread each; GLFW
// windows on this thread, as GLFW requires), the field, the menu, and then
// feeds the walls one packet a frame until the frame count, a closed window,
// Ctrl-C or a failed wall stops it. The configuration's field is read on a
// thread from the start: a read that takes longer than a moment (a large
// file) goes on while the walls open their contexts, programs and buffers,
// and packet 0, which carries the field, waits for both. Members are
// declared so that they go in the reverse order: walls before the menu whose
// overlay they draw, both before the windows' library.
#pragma once

#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <vector>

#include "app/app.h"
#include "app/desktop_input.h"
#include "app/field_editor.h"
#include "app/field_stream.h"
#include "app/fluid_driver.h"
#include "app/hash_log.h"
#include "app/helicopter_controller.h"
#include "app/menu/legend_host.h"
#include "app/menu/menu_host.h"
#include "app/molecule_push.h"
#include "app/movie_recorder.h"
#include "app/obstacle_drag.h"
#include "app/obstacle_driver.h"
#include "app/playback_meter.h"
#include "app/scene_setup.h"
#include "app/tracking/tracking_input.h"
#include "contexts/platform/glfw_window.h"
#include "contexts/render/render_context.h"
#include "core/cave/viewer.h"
#include "core/flow/polyline_color.h"
#include "core/sim/frame_channel.h"
#include "core/sim/main_context.h"
#include "core/sim/session_log.h"
#include "core/sim/state_mirror.h"
#include "core/util/frame_pacer.h"
#include "core/util/image_files.h"

namespace sandstorm {

class ClusterLink;

class AppRun {
 public:
  // The configuration as App prepared it (cluster mode: already localized to this rank).
  // `field`: the configuration's [field], already read; empty: read here.
  AppRun(const AppConfig& config, const AppOptions& options, bool headless, ClusterLink* cluster,
         std::optional<FieldSource> field = std::nullopt);
  // Walls still opening (a start() that threw) are told to stop before they are joined.
  ~AppRun();
  // The whole run: start(), frames until the end (or Ctrl-C), stop(). Returns the exit code.
  int execute();

  // A run stepped by its caller (SteppedRun, the Python module; one process):
  // start() opens the walls (false: they could not), advance() makes one
  // frame's packet (false: the run is over: a wall failed, a window closed,
  // the frame count reached), stop() ends it and returns the exit code.
  // The observer, set before start(), sees every wall's every frame on the
  // wall's drawing thread, after its picture and overlays are drawn.
  using FrameObserver = std::function<void(std::size_t wall, WallRenderer&, const FramePacket&)>;
  void setFrameObserver(FrameObserver observer) { observer_ = std::move(observer); }
  // Set before start(): what the main context does with the field once it is read.
  void setFieldSeeding(FieldSeeding seeding) { seeding_ = std::move(seeding); }
  bool start();
  bool advance();
  int stop();
  int framesMade() const { return frames_; }
  MainContext& mainContext() { return main_; }
  const std::vector<std::unique_ptr<RenderWall>>& walls() const { return walls_; }
  const std::shared_ptr<const HeightMap>& terrain() const { return terrain_; }

 private:
  using Clock = std::chrono::steady_clock;

  void openWindowLibrary();
  std::vector<int> wallGpus() const;
  void openWalls();
  // The field read into the main context, with what builds on it (the
  // helicopter's, the editor's primitives, a watched folder's stream).
  void takeField();
  std::unique_ptr<GlContext> uploadContext(const GlContext& context, const WallSpec& spec, int gpu);
  void openMenu();
  void openLegend();
  void dumpStreamlines(const WallRenderer& wall, const FramePacket& packet);
  void dumpTrails(const WallRenderer& wall, const FramePacket& packet);
  static LineColoring lineColoring(const WallRenderer& wall, const FramePacket& packet);
  void hookWalls();
  void runCluster();
  void track(float dt);
  std::optional<WandMenuTarget> menuTarget() const;
  void showMenu(float dt, const std::vector<std::string>& probe);
  void beforePacket(float dt);
  void chooseSolverDevice();
  void autoColorRange(const ParticleState& state);
  std::vector<std::string> probeLines(const ParticleState& state, const FieldUpdate* field,
                                      const FramePacket* last) const;
  void showMirrorLegend(float dt, std::shared_ptr<const FramePacket> packet);
  void pickProbe();
  // Where a click on a wall's window points in the world; none off the walls.
  std::optional<WorldRay> rayThrough(const DesktopInput::Click& click) const;
  void dragObstacle(float dt);
  // A watched field's steps read since the last frame, or a replayed session's.
  void streamField();
  void appendFieldStep(double time, const std::string& file,
                       std::shared_ptr<const VectorField> field, std::uint32_t completeAt);
  glm::vec3 fieldCentre(const WorldRay& ray) const;
  void reportProgress(Clock::time_point now);
  // After frame frames_'s packet: the series' playback measured.
  void meterPlayback(Clock::time_point now);
  int finish();

  const AppConfig& config_;
  const AppOptions& options_;
  const bool headless_;
  ClusterLink* const cluster_;
  const std::filesystem::path configDir_;
  const std::filesystem::path projectRoot_;  // menu choices and recorded fields are named from here
  const int lastFrame_;                      // -1: until a window closes
  // run.stats_warmup, or half a run too short for it (statsWarmup()).
  const std::uint32_t statsWarmup_;

  FieldSource field_;
  FieldSeeding seeding_;
  std::future<FieldSource> fieldRead_;  // the configuration's field while it is read
  std::shared_ptr<const HeightMap> terrain_;
  MainContext main_;
  std::unique_ptr<SessionRecorder> recorder_;
  SessionLog replay_;
  std::size_t replayNavigationAt_ = 0, replayFieldAt_ = 0;
  std::size_t replayStepAt_ = 0;
  std::unique_ptr<FieldStream> fieldStream_;  // a watched field (rank 0, not replaying)
  PlaybackMeter playback_{statsWarmup_};      // a series' steps a second (rank 0)
  void loadField(const std::string& choice);
  std::unique_ptr<TrackingInput> tracking_;  // null: no tracker (or not the main context's rank)
  HelicopterController helicopter_;
  FluidDriver fluid_;   // the live flow solver, while solver.enabled
  FieldEditor editor_;  // the field editor's primitives added to the field
  ObstacleDriver obstaclePaths_;
  ObstacleDrag obstacleDrag_;
  MoleculePush moleculePush_;
  std::unique_ptr<HeadTracker> head_;
  Navigation navigation_;

  std::unique_ptr<GlfwLibrary> glfw_;
  bool operatorWindow_ = false;
  FrameChannel channel_;
  RenderContext::SwapBarrier barrier_;
  std::vector<GlfwWindow*> windows_;      // every wall's window, in wall order
  std::vector<GlfwWindow*> wallWindows_;  // per wall: its window, or null offscreen
  int menuWall_ = -1;
  std::unique_ptr<DesktopInput> input_;
  std::unique_ptr<MenuHost> menu_;
  std::unique_ptr<LegendHost> legend_;
  std::unique_ptr<StateMirror> mirror_;  // ranks other than 0: the packets' state, for the legend
  std::shared_ptr<const FramePacket> lastPacket_;  // the newest packet made (probe, menu)
  std::optional<std::uint32_t> colorRangeFrom_;    // the measurement last made the colour range
  std::uint32_t nextColorRangeAt_ = 0;
  std::unique_ptr<ImageFiles> images_;  // --screenshot's PNGs; before walls_: they queue them
  std::vector<std::unique_ptr<RenderWall>> walls_;        // one a wall, by index
  std::vector<std::unique_ptr<RenderContext>> contexts_;  // after walls_: joined first
  HashLog hashes_;
  FrameObserver observer_;
  std::unique_ptr<MovieRecorder> movie_;  // --movie; after walls_: they hand it pictures

  int frames_ = 0;
  bool failed_ = false;
  Clock::time_point start_, lastReport_, lastTick_;
  FramePacer pacer_{config_.run.maxFps};
};

}  // namespace sandstorm
