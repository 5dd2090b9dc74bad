// AppConfig: everything a run is configured with, as read from a TOML file in
// config/ (see config/README.md for the keys). Loading validates every key
// before anything starts: a bad file yields one Error naming the file, line
// and key, and no half-applied configuration.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/cave/wall.h"
#include "core/config/byte_size.h"
#include "core/config/gpu_tuning.h"
#include "core/field/box.h"
#include "core/field/field_placement.h"
#include "core/obstacles/obstacle_path.h"
#include "core/sim/particle_state.h"

namespace sandstorm {

// LeftEye, RightEye: a wall that shows one eye's view, as each projector of a
// passive-stereo pair does; two such walls on two GPUs share a wall's stereo.
enum class StereoMode { Mono, QuadBuffer, SideBySide, TopBottom, Anaglyph, LeftEye, RightEye };

struct WindowSpec {
  int monitor = 0;
  glm::ivec2 position{-1, -1};  // -1: the window manager decides
  glm::ivec2 size{1280, 720};
  bool fullscreen = false;
  bool decorated = true;
};

// A conventional perspective camera in place of wall corners (desktop use).
struct CameraSpec {
  glm::vec3 position{10.0f, -10.0f, 5.0f};
  glm::vec3 target{0.0f, 0.0f, 3.0f};
  float fovDegrees = 50.0f;
};

struct WallSpec {
  std::string name;
  WallCorners corners;
  std::optional<CameraSpec> camera;    // set: a perspective camera, corners unused
  std::optional<WindowSpec> window;    // set: a GLFW window; otherwise offscreen (EGL)
  glm::ivec2 offscreenSize{960, 540};  // image size of an offscreen wall
  StereoMode stereo = StereoMode::Mono;
  bool menu = false;  // show the menu panel on this wall
  // Show the colour legend here (when render.legend is on); with no wall
  // marked, the menu's wall or else the first shows it.
  bool legend = false;
  int rank = 0;      // cluster mode: the MPI rank that drives this wall
  std::string host;  // cluster mode: or the first rank on this host (overrides rank)
  // An offscreen wall's GPU (EGL device index); unset: run.gpus decides (GPU 0
  // unless round-robin). Windows draw on their display's GPU.
  std::optional<int> gpu;
  int line = 0;  // where the wall was declared, for messages
};

enum class HeadMode { Fixed, Scripted, Desktop };

struct HeadKeyframe {
  float time = 0.0f;  // s
  glm::vec3 position{0.0f};
};

struct HeadSpec {
  HeadMode mode = HeadMode::Fixed;
  glm::vec3 position{0.0f, 0.0f, 1.7f};
  float yawDegrees = 90.0f;  // the direction the head faces, counter-clockwise from +x (90: +y)
  std::optional<glm::vec3> right;  // the eyes' axis itself (a tilted head), instead of yaw
  float eyeSeparation = 0.065f;
  std::vector<HeadKeyframe> path;  // scripted
  bool loop = true;
};

// Where the world (field, scene, particles) sits in the room: navigation.
struct NavigationSpec {
  glm::vec3 offset{0.0f};
  float yawDegrees = 0.0f;
  float scale = 1.0f;
  float flySpeed = 1.5f;       // m/s at full joystick (tracked wand)
  float turnSpeedDeg = 45.0f;  // degrees/s at full joystick (tracked wand)
};

enum class TrackingSource { None, DTrack, Replay };

// A tracker for the head and the wand (config [tracking], core/tracking/).
struct TrackingSpec {
  TrackingSource source = TrackingSource::None;
  int port = 5000;        // UDP port DTrack sends to
  std::string multicast;  // a multicast group to join ("239.0.0.1"); empty: unicast
  // The DTrack controller's addresses: datagrams from any other host are
  // dropped and counted. Empty: any host (a warning at start).
  std::vector<std::string> senders;
  std::string interfaceAddress;  // the local address to listen on; empty: every interface
  int headBody = 0;              // the glasses: standard body id (6d)
  int wandFlystick = 0;          // the wand: Flystick id (6df2 / 6df)
  // Tracker room -> Sandstorm room: room = offset + rotation * (millimetres / 1000).
  glm::vec3 offset{0.0f};
  glm::mat3 rotation{1.0f};
  float staleMs = 250.0f;     // no measurement this long: hold the last pose, "tracking lost"
  glm::vec3 eyeOffset{0.0f};  // glasses body origin -> between the eyes (body axes, metres)
  // The bodies' own axes (body coordinates): which way is right/up on the
  // glasses, forward/up on the wand. The defaults fit bodies calibrated
  // "due to room" while facing +y in a z-up tracker room.
  glm::vec3 headRight{1.0f, 0.0f, 0.0f}, headUp{0.0f, 0.0f, 1.0f};
  glm::vec3 wandForward{0.0f, 1.0f, 0.0f}, wandUp{0.0f, 0.0f, 1.0f};
  int triggerButton = 0;     // clicks the menu
  int grabButton = 1;        // grabs emitters
  float grabRadius = 0.25f;  // m (room): how near the ray an emitter handle is grabbed
  float rayLength = 20.0f;   // m (room): the ray's length when it hits nothing
  int line = 0;              // where [tracking] was declared, for messages
};

struct FieldSpec {
  std::string source =
      "analytic";  // "analytic" or a file path (resolved against the config's folder)
  std::string name =
      "tornado";  // analytic field, or the array/grid name in a file (empty: the only one)
  glm::ivec3 dims{48, 48, 32};  // baking resolution of an analytic field
  glm::ivec3 resolution{0};     // a file's grid resampled to this; 0: the file's own
  Box bounds{{-6.0f, -6.0f, 0.0f}, {6.0f, 6.0f, 10.0f}};
  std::map<std::string, double> params;  // analytic field parameters
  FieldPlacement placement;
  glm::vec3 rotationDegrees{0.0f};  // the turns placement.rotation was made from (x, y, z)
  // A field a running simulation writes: a folder source is always watched
  // for new steps, a .pvd when `watch` is set (app/field_stream.h).
  bool watch = false;
  double stepInterval = 1.0;   // s between a folder's steps (a .pvd gives its own times)
  double waitSeconds = 60.0;   // how long the start waits for a watched source's first step
  double settleSeconds = 0.2;  // a step's file is complete once unchanged this long
  // The largest grid (and a series' steps in memory together) a file may
  // load into, in bytes; 0: automatic, half this machine's memory
  // (fieldMemoryBudget()).
  std::uint64_t memoryBudget = 0;
  // Steps of a series read ahead of playback, beyond the two being blended.
  int readAhead = 2;
  // The step after the pair in use uploaded to each GPU ahead of need
  // (contexts/particles/grid_prefetch.h): a third grid on the GPU and a
  // step's texels of host memory, for a step that costs its frame no upload.
  bool uploadAhead = true;
  // precision = "half": 16-bit floats on the GPU (VectorField::roundToHalf).
  bool halfPrecision = false;
  // precision = "auto" (the default): floats, unless the field's grids would
  // not fit on the GPU as floats; then halves (core/io/precision_choice.h).
  bool autoPrecision = true;
  // storage: how an OpenVDB grid is kept: "auto" sparse when its active
  // voxels fill under half their box or a dense grid would not fit, "dense"
  // densified over the box, "sparse" as NanoVDB (core/field/sparse_field.h).
  enum class Storage { Auto, Dense, Sparse } storage = Storage::Auto;
};

// FieldSpec::memoryBudget, the automatic one worked out: half the host's
// memory (a field is read into host memory before the GPU gets it), 2 GiB
// where the system does not say.
inline std::uint64_t fieldMemoryBudget(const FieldSpec& spec) {
  if (spec.memoryBudget > 0) return spec.memoryBudget;
  const std::uint64_t host = hostMemoryBytes();
  return host > 0 ? host / 2 : std::uint64_t{2} << 30;
}

struct SceneSpec {
  std::string terrain = "flat";  // "flat", or a height map file (16-bit PGM / PNG)
  float groundHeight = 0.0f;
  Box terrainBounds{{-50.0f, -50.0f, 0.0f},
                    {50.0f, 50.0f, 8.0f}};  // xy extent and height range of a map
  bool helicopter = false;                  // the downdraft demo's helicopter and its controls
};

struct RunSpec {
  std::uint64_t seed = 1;
  std::size_t capacity = 1u << 20;       // initial particle buffer size
  std::size_t capacityLimit = 1u << 26;  // raising sim.maximum grows the buffers up to this
  float fixedDt = 0.0f;                  // > 0: fixed steps; 0: the main context's clock
  int frames = 0;                        // 0: until a window closes
  double maxFps = 0.0;                   // > 0: frames a second at most (FramePacer)
  std::string backend =
      "compute";  // or "tf-gs" (the thesis's); compute is faster (docs/PERFORMANCE.md)
  // One simulation per GPU: the walls whose contexts can share objects (all
  // windows, or all offscreen walls, of one process) draw one wall's particles.
  bool sharedSimulation = false;
  float nearPlane = 0.05f;
  float farPlane = 500.0f;
  int statsWarmup = 60;  // frames left out of the run statistics (start-up, filling)
  // Offscreen walls: one GL context (and thread) draws them all, or one each.
  // Contexts on one GPU take turns on it: one is much faster (docs/PERFORMANCE.md).
  enum class OffscreenContexts { One, PerWall };
  OffscreenContexts offscreenContexts = OffscreenContexts::One;
  // Offscreen walls without a `gpu` of their own: all on GPU 0, or wall i (the
  // i-th offscreen wall this process draws) on GPU i mod the GPUs there are.
  bool gpusRoundRobin = false;
};

// Cluster mode (mpirun, app/cluster/): how rank 0 feeds the other ranks.
struct ClusterSpec {
  float timeoutSeconds = 10.0f;  // a rank that does not answer this long stops the run
  float startupTimeoutSeconds =
      120.0f;              // the same before the first frame (loading fields, opening windows)
  bool readField = false;  // field = "read": every rank loads the field itself (checked by hash)
  // steps = "read": every rank reads a streamed series' steps itself (from a
  // shared file system); "broadcast": rank 0 sends them.
  bool readSteps = true;
  int chunkKiB = 4096;  // field grids travel in chunks of this size
  int fieldCache = 4;   // grids each rank keeps (a time-varying field's frames)
  bool roundRobin =
      false;  // walls = "round-robin": wall i on rank i % ranks, whatever rank/host say
  // [cluster] ranks = {front = 1}, hosts = {front = "node-a"}: placement of
  // walls defined elsewhere (an included file); applied once every file is read.
  struct Placement {
    std::string wall;
    std::optional<int> rank;
    std::string host;
    std::string where;  // "file:line: cluster.ranks.front", for messages
  };
  std::vector<Placement> placements;
};

// The operator's menu in a window of its own (a console monitor in a CAVE).
struct MenuSpec {
  std::optional<WindowSpec> operatorWindow;
};

struct AppConfig {
  std::filesystem::path path;    // as the user named it (messages)
  std::filesystem::path folder;  // its folder, absolute, links followed: relative paths start here
  ParticleState particles;
  FieldSpec field;
  SceneSpec scene;
  HeadSpec head;
  NavigationSpec navigation;
  TrackingSpec tracking;
  RunSpec run;
  GpuTuning gpu;
  MenuSpec menu;
  ClusterSpec cluster;
  std::vector<WallSpec> walls;
  // Each [[obstacle]]'s scripted path (empty: none), by obstacle index.
  std::vector<ObstaclePath> obstaclePaths;

  bool anyWindow() const;
  // The OpenGL contexts a run of this configuration draws with, each in its
  // own thread: a window each, the operator window, and the offscreen walls'
  // (one each, or with offscreen_contexts = "one" one for each GPU they name;
  // run.gpus = "round-robin" counts as one GPU here).
  int glContexts() const;
};

// Reads and validates a configuration. `monitorCount` (when known) checks
// windows' monitor indices. Throws Error: "config/cave4.toml:14: wall[1].lower_left: ...".
AppConfig loadConfig(const std::filesystem::path& path,
                     std::optional<int> monitorCount = std::nullopt);
AppConfig parseConfig(const std::string& text, const std::filesystem::path& name,
                      std::optional<int> monitorCount = std::nullopt);

const char* toString(StereoMode mode);

}  // namespace sandstorm
