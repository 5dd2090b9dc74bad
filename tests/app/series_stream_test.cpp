// A series streamed from disk in the application: a long series plays in the
// memory of a few steps (the run's peak resident memory against the same
// run over a series a tenth as long), and so does a watched folder a
// simulation keeps filling, a recorded run replays to the same
// particles, a step that cannot be read stops playback and the run goes on,
// and a budget that cannot hold two steps is refused naming the settings.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <regex>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/io/vti_writer.h"
#include "tests/app/run_process.h"

namespace sandstorm {
namespace {

namespace fs = std::filesystem;

constexpr int kSide = 64;  // a step: 64^3 points, 3 MiB

// Step k: a wind turning with k, so every step moves the particles differently.
VectorField stepField(int k) {
  const float a = 0.3f * float(k);
  return VectorField(Box{{-3, -3, 0}, {3, 3, 4}}, glm::ivec3(kSide),
                     std::vector<glm::vec3>(std::size_t(kSide) * kSide * kSide,
                                            glm::vec3(std::cos(a), std::sin(a), 0.2f)));
}

std::string stepName(int k) {
  char name[32];
  std::snprintf(name, sizeof(name), "step_%03d.vti", k);
  return name;
}

// A .pvd of `steps` steps 0.05 s apart, and a configuration that plays it
// once (three frames a step at 1/60 s) with `extra` in [field].
fs::path writeRun(const fs::path& dir, int steps, const std::string& extra = "read_ahead = 1") {
  std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\">\n<Collection>\n";
  for (int k = 0; k < steps; ++k) {
    writeVti(dir / stepName(k), stepField(k));
    pvd +=
        "<DataSet timestep=\"" + std::to_string(0.05 * k) + "\" file=\"" + stepName(k) + "\"/>\n";
  }
  pvd += "</Collection>\n</VTKFile>\n";
  std::ofstream(dir / "series.pvd") << pvd;
  std::ofstream out(dir / "series.toml");
  out << R"([run]
fixed_dt = 0.016666668
capacity = 8192
# A display's pace: a GPU headless runs frames far shorter than a step's read,
# and playback would spend the run waiting.
max_fps = 120

[field]
source = "series.pvd"
)" << extra
      << R"(

[field_playback]
loop = false

[sim]
maximum = 4000
motion = "tracer"
boundary = "clamp"

[[emitter]]
shape = "sphere"
position = [0.0, 0.0, 2.0]
radius = 1.0
rate = 6000.0
lifetime = 20.0

[[wall]]
name = "view"
camera = { position = [0.0, -9.0, 2.0], target = [0.0, 0.0, 2.0], fov_deg = 50.0 }
offscreen = { size = [48, 32] }
)";
  return dir / "series.toml";
}

struct Measured {
  test::ProcessResult result;
  long peakKiB = 0;  // the child's peak resident memory
};

// Runs the application as a child of its own, for its peak resident memory.
Measured runMeasured(const std::string& args) {
  Measured m;
  const fs::path out =
      fs::temp_directory_path() / ("sandstorm-measured-" + std::to_string(getpid()));
  const std::string cmd = std::string("cd '") + SANDSTORM_SOURCE_DIR + "' && exec '" +
                          SANDSTORM_BINARY + "' " + args + " > '" + out.string() + "' 2>&1";
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  m.result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  m.result.output = test::readBytes(out);
  m.peakKiB = usage.ru_maxrss;
  fs::remove(out);
  return m;
}

int stepsRead(const std::string& output) {
  std::smatch m;
  if (!std::regex_search(output, m, std::regex("field series: (\\d+) step\\(s\\) read"))) return -1;
  return std::stoi(m[1]);
}

// Runs the six-step and the sixty-step configuration for `frames` frames:
// both must end well, every step after the first counted by `counted` (5
// and 59), and the long run's peak resident memory within 80 MiB of the
// short one's (held at once, its 54 more steps of 3 MiB would take 162 MiB
// more; NVIDIA's driver alone made the long run 34-41 MiB larger on an H200:
// docs/PERFORMANCE.md, "The pair blended once a frame"). `capacity`: what
// the long run says of the steps it keeps.
void expectFlatMemory(const fs::path& shortRun, const fs::path& longRun, int frames,
                      const std::function<int(const std::string&)>& counted,
                      const std::string& capacity) {
  const std::string count = "' --frames " + std::to_string(frames);
  const Measured few = runMeasured("--config '" + shortRun.string() + count);
  const Measured many = runMeasured("--config '" + longRun.string() + count);
  ASSERT_EQ(few.result.exitCode, 0) << few.result.output;
  ASSERT_EQ(many.result.exitCode, 0) << many.result.output;
  EXPECT_EQ(counted(few.result.output), 5) << few.result.output;
  EXPECT_EQ(counted(many.result.output), 59) << many.result.output;
  EXPECT_NE(many.result.output.find(capacity), std::string::npos) << many.result.output;
  const long extraKiB = many.peakKiB - few.peakKiB;
  EXPECT_LT(extraKiB, 80 * 1024) << "peak " << many.peakKiB << " KiB against " << few.peakKiB;
}

TEST(SeriesStream, ALongSeriesPlaysInTheMemoryOfAFewSteps) {
  // Both play every step to the end (60 steps: 180 frames, plus any waits),
  // reading each step after the first.
  expectFlatMemory(writeRun(test::scratchDir("series-short"), 6),
                   writeRun(test::scratchDir("series-long"), 60), 300, stepsRead,
                   "streamed: at most 3 steps");
}

// The run of writeRun on a watched folder (a running simulation's steps,
// field.source a folder) instead of the .pvd, following the newest step.
fs::path writeWatched(const fs::path& dir, int steps) {
  const fs::path run = writeRun(dir, steps);
  fs::create_directories(dir / "steps");
  for (int k = 0; k < steps; ++k)
    fs::rename(dir / stepName(k), dir / "steps" / stepName(k));
  std::string text = test::readBytes(run);
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"source = \"series.pvd\"",
                                            "source = \"steps\"\nstep_interval = 0.05"},
        {"loop = false", "follow = true"}}) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  std::ofstream(run) << text;
  return run;
}

int joinedSteps(const std::string& output) {
  int n = 0;
  for (std::size_t at = output.find(") joins the field at frame "); at != std::string::npos;
       at = output.find(") joins the field at frame ", at + 1))
    ++n;
  return n;
}

TEST(SeriesStream, AWatchedFolderKeepsTheMemoryOfAFewStepsHoweverManyJoin) {
  // Every step the simulation wrote joins the field (the first one started it).
  expectFlatMemory(writeWatched(test::scratchDir("watched-short"), 6),
                   writeWatched(test::scratchDir("watched-long"), 60), 240, joinedSteps,
                   "at most 3 steps in memory");
}

TEST(SeriesStream, ARecordedRunReplaysToTheSameParticles) {
  const fs::path dir = test::scratchDir("series-replay");
  const fs::path run = writeRun(dir, 24);
  const std::string base = "--config '" + run.string() + "' --frames 90 --hash-log ";
  const test::ProcessResult recorded =
      test::runSandstorm(base + "'" + (dir / "live.log").string() + "' --record '" +
                         (dir / "run.session").string() + "'");
  ASSERT_EQ(recorded.exitCode, 0) << recorded.output;
  const test::ProcessResult replayed =
      test::runSandstorm(base + "'" + (dir / "replay.log").string() + "' --replay '" +
                         (dir / "run.session").string() + "'");
  ASSERT_EQ(replayed.exitCode, 0) << replayed.output;
  const std::string live = test::readBytes(dir / "live.log");
  EXPECT_FALSE(live.empty());
  EXPECT_EQ(live, test::readBytes(dir / "replay.log"));
  // The steps did matter: a still field (the first step alone) moves the particles elsewhere.
  const fs::path still = dir / "still";
  fs::create_directories(still);
  const fs::path stillRun = writeRun(still, 1);
  const test::ProcessResult alone =
      test::runSandstorm("--config '" + stillRun.string() + "' --frames 90 --hash-log '" +
                         (dir / "still.log").string() + "'");
  ASSERT_EQ(alone.exitCode, 0) << alone.output;
  EXPECT_NE(live, test::readBytes(dir / "still.log"));
}

TEST(SeriesStream, AStepThatCannotBeReadStopsPlaybackAndTheRunGoesOn) {
  const fs::path dir = test::scratchDir("series-broken");
  const fs::path run = writeRun(dir, 8);
  const std::string whole = test::readBytes(dir / stepName(4));
  std::ofstream(dir / stepName(4), std::ios::binary | std::ios::trunc)
      .write(whole.data(), std::streamsize(whole.size() / 3));
  const test::ProcessResult r = test::runSandstorm("--config '" + run.string() + "' --frames 60");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find(stepName(4)), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("playback stops at the last pair read (t = 0.1 to 0.15 s)"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("stats: 60 frames"), std::string::npos) << r.output;
}

// The statistics say how fast the series played over the measured frames: a
// step every three frames, so 60 frames after the warm-up pass 20 steps less
// the frames that waited for one (each costs a step a third of its frames).
TEST(SeriesStream, TheStatisticsSayTheStepsPlayedASecondOverTheMeasuredFrames) {
  const fs::path dir = test::scratchDir("series-rate");
  const fs::path run = writeRun(dir, 60);
  std::string config = test::readBytes(run);
  config.replace(config.find("max_fps = 120"), 13, "max_fps = 120\nstats_warmup = 30");
  std::ofstream(run) << config;
  const fs::path json = dir / "stats.json";
  const test::ProcessResult r = test::runSandstorm("--config '" + run.string() +
                                                   "' --frames 90 --stats '" + json.string() + "'");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string text = test::readBytes(json);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      text, m,
      std::regex("\"series\": \\{\"frames\": (\\d+), \"steps_played\": (\\d+), \"seconds\": "
                 "([-0-9.e+]+), \"steps_per_s\": ([-0-9.e+]+), \"frames_waited\": (\\d+)\\}")))
      << text;
  const int frames = std::stoi(m[1]), played = std::stoi(m[2]), waited = std::stoi(m[5]);
  const double seconds = std::stod(m[3]), rate = std::stod(m[4]);
  EXPECT_EQ(frames, 60);
  // Frames 30 to 89: 59 intervals at a step every three frames, but for the waits.
  EXPECT_LE(played, 20);
  EXPECT_GE(played, (59 - waited) / 3 - 1) << waited << " frames waited";
  EXPECT_GT(seconds, 0.0);
  EXPECT_NEAR(rate, played / seconds, 1e-3 * rate + 1e-9);
  EXPECT_NE(r.output.find("field series over the measured frames: " + std::to_string(played) +
                          " step(s) played in "),
            std::string::npos)
      << r.output;
}

TEST(SeriesStream, ABudgetThatCannotHoldTwoStepsIsRefusedNamingTheSettings) {
  const fs::path dir = test::scratchDir("series-budget");
  const test::ProcessResult r = test::runSandstorm(
      "--config '" + writeRun(dir, 4, "memory_budget = \"5 MiB\"").string() + "' --frames 2");
  EXPECT_NE(r.exitCode, 0);
  for (const char* part : {"series.pvd", "field.memory_budget", "field.resolution", "5 MiB"})
    EXPECT_NE(r.output.find(part), std::string::npos) << part << " in " << r.output;
  // A budget for three steps but not four reads one fewer ahead, and says so.
  const test::ProcessResult fewer = test::runSandstorm(
      "--config '" + writeRun(dir, 4, "memory_budget = \"10 MiB\"\nread_ahead = 2").string() +
      "' --frames 2");
  EXPECT_EQ(fewer.exitCode, 0) << fewer.output;
  EXPECT_NE(fewer.output.find("field.read_ahead = 2 needs 4 steps"), std::string::npos)
      << fewer.output;
}

}  // namespace
}  // namespace sandstorm
