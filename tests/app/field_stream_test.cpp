// Fields from a running simulation: the app runs headless on a folder that a
// "simulation" (this test) fills while it runs. Each new step joins the field
// within one frame of being found complete; a corrupt step in the middle is
// skipped with a message naming it and the run goes on; the session records
// the steps at their frames, so a replay without the folder's timing draws the
// same particles; and without the new steps the particles differ.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <regex>
#include <thread>

#include <sys/types.h>

#include "core/io/vti_writer.h"
#include "tests/app/run_process.h"

namespace sandstorm {
namespace {

namespace fs = std::filesystem;

// A uniform wind over the box, as a small grid.
VectorField wind(glm::vec3 v) {
  return VectorField(Box{{-3, -3, 0}, {3, 3, 4}}, glm::ivec3(4, 4, 4),
                     std::vector<glm::vec3>(64, v));
}

// Writes a step as a simulation that renames a finished file into place does not:
// straight into the folder, in two halves a little apart, so the watcher sees it grow.
void writeStep(const fs::path& file, const VectorField& field) {
  const fs::path temp = file.parent_path().parent_path() / (file.filename().string() + ".w");
  writeVti(temp, field);
  const std::string bytes = test::readBytes(temp);
  std::ofstream out(file, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size() / 2));
  out.flush();
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  out.write(bytes.data() + bytes.size() / 2, std::streamsize(bytes.size() - bytes.size() / 2));
}

std::string config(const fs::path& dir) {
  std::ofstream out(dir / "stream.toml");
  out << R"(# A watched folder of steps (tests/app/field_stream_test.cpp writes it).
[run]
fixed_dt = 0.016666668
capacity = 8192
# A CAVE's pace: "joins within a frame of being found" means a frame of a
# display's length; a fast GPU headless runs frames shorter than a read.
max_fps = 120

[field]
source = "steps"
step_interval = 0.5

[field_playback]
follow = true

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
  return (dir / "stream.toml").string();
}

struct Joined {
  double time;
  std::uint32_t frame, complete;
};

std::vector<Joined> joined(const std::string& output) {
  std::vector<Joined> out;
  const std::regex line(
      R"(the step at t = ([0-9.e+-]+) s \([^)]*\) joins the field at frame ([0-9]+) \(found complete during frame ([0-9]+))");
  for (auto it = std::sregex_iterator(output.begin(), output.end(), line);
       it != std::sregex_iterator(); ++it)
    out.push_back({std::stod((*it)[1]), std::uint32_t(std::stoul((*it)[2])),
                   std::uint32_t(std::stoul((*it)[3]))});
  return out;
}

TEST(FieldStream, StepsWrittenDuringTheRunJoinTheFieldAndACorruptOneIsSkipped) {
  const fs::path dir = test::scratchDir("field-stream");
  fs::create_directories(dir / "steps");
  writeVti(dir / "steps" / "step_000.vti", wind({1, 0, 0}));
  const std::string cfg = config(dir);
  const std::string args = "--config " + cfg + " --headless --hash-log ";

  // The run, until stopped (SIGTERM ends it cleanly), read line by line on a
  // thread; the steps are written once frames begin. Stopped by the test, not
  // after a count of frames, so that a GPU however fast still runs while the
  // steps come.
  std::atomic<bool> begun{false}, lastJoined{false};
  std::atomic<pid_t> pid{0};
  test::ProcessResult live;
  std::thread runner([&] {
    const std::string cmd = std::string("cd '") + SANDSTORM_SOURCE_DIR + "' && ('" +
                            SANDSTORM_BINARY + "' " + args + (dir / "live.txt").string() +
                            " --frames 0 --record " + (dir / "live.session").string() +
                            " 2>&1 & echo \"pid $!\"; wait $!)";
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return;
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe)) {
      int p = 0;
      if (pid == 0 && std::sscanf(buffer, "pid %d", &p) == 1) {
        pid = pid_t(p);
        continue;
      }
      live.output += buffer;
      if (live.output.find("frames begin") != std::string::npos) begun = true;
      if (live.output.find("the step at t = 1.5 s") != std::string::npos) lastJoined = true;
    }
    const int status = pclose(pipe);
    live.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    begun = true;
  });
  while (!begun)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const auto pause = [] { std::this_thread::sleep_for(std::chrono::milliseconds(250)); };
  pause();
  writeStep(dir / "steps" / "step_001.vti", wind({0, 1, 0}));
  pause();
  {  // a corrupt step: not a VTK file at all
    std::ofstream bad(dir / "steps" / "step_002.vti");
    bad << "<?xml version=\"1.0\"?><VTKFile type=\"ImageData\"><ImageData garbage";
  }
  pause();
  writeStep(dir / "steps" / "step_003.vti", wind({-1, 0, 0.5f}));
  // Once the last step has joined (or after a minute), a little more flow, then the end.
  for (int i = 0; i < 6000 && !lastJoined; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  pause();
  if (pid > 0) kill(pid, SIGTERM);
  runner.join();
  ASSERT_EQ(live.exitCode, 0) << live.output;
  const std::vector<Joined> steps = joined(live.output);
  ASSERT_EQ(steps.size(), 2u) << live.output;  // 001 and 003; 000 was the start's
  EXPECT_EQ(steps[0].time, 0.5);
  EXPECT_EQ(steps[1].time, 1.5);  // 002 took its place in the order and was skipped
  for (const Joined& j : steps)
    EXPECT_LE(j.frame - j.complete, 1u) << "t = " << j.time;
  EXPECT_NE(live.output.find("step_002.vti) was skipped"), std::string::npos) << live.output;
  const std::size_t frames = test::readLines(dir / "live.txt").size();
  ASSERT_GT(frames, steps[1].frame + 2) << "the run ended too soon to show the last step";

  // The session holds the steps at their frames: a replay of as many frames
  // draws the same particles.
  const std::string count = " --frames " + std::to_string(frames) + " ";
  const auto replay = test::runSandstorm(args + (dir / "replay.txt").string() + count +
                                         "--replay " + (dir / "live.session").string());
  ASSERT_EQ(replay.exitCode, 0) << replay.output;
  EXPECT_EQ(test::readLines(dir / "live.txt"), test::readLines(dir / "replay.txt"));
  // Without the steps (the start's field only) the particles end elsewhere.
  fs::remove_all(dir / "steps");
  fs::create_directories(dir / "steps");
  writeVti(dir / "steps" / "step_000.vti", wind({1, 0, 0}));
  const auto still = test::runSandstorm(args + (dir / "still.txt").string() + count);
  ASSERT_EQ(still.exitCode, 0) << still.output;
  EXPECT_NE(test::readLines(dir / "still.txt").back(), test::readLines(dir / "live.txt").back());
}

TEST(FieldStream, AnEmptyFolderStopsTheStartAfterWaitingWithAClearMessage) {
  const fs::path dir = test::scratchDir("field-stream-empty");
  fs::create_directories(dir / "steps");
  std::string text = test::readBytes(config(dir));
  text.replace(text.find("step_interval = 0.5"), 19, "step_interval = 0.5\nwait_s = 0.3");
  std::ofstream(dir / "stream.toml") << text;
  const auto r = test::runSandstorm("--config " + (dir / "stream.toml").string() +
                                    " --headless --frames 3 --log-level debug");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.output.find("no complete step came within 0.3 s (field.wait_s)"), std::string::npos)
      << r.output;
  // The wait outlasted a moment, so the walls opened meanwhile; the error still ends the run.
  EXPECT_NE(r.output.find("the walls open while the field is read"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("frames begin"), std::string::npos) << r.output;
}

// A folder that holds its series' .pvd is watched, its steps timed by their
// order: the run says so and names the .pvd that plays the series' own times.
TEST(FieldStream, AFolderBesideItsPvdSaysTheCollectionPlaysItsOwnTimes) {
  const fs::path dir = test::scratchDir("field-stream-pvd");
  fs::create_directories(dir / "run");
  writeVti(dir / "run" / "step_0.vti", wind({1, 0, 0}));
  writeVti(dir / "run" / "step_1.vti", wind({2, 0, 0}));
  std::ofstream(dir / "run" / "run.pvd")
      << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n"
         "<DataSet timestep=\"0\" file=\"step_0.vti\"/>\n<DataSet timestep=\"0.25\" "
         "file=\"step_1.vti\"/>\n</Collection>\n</VTKFile>\n";
  const auto r =
      test::runSandstorm((dir / "run").string() + " --headless --frames 1 --set sim.maximum=500");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("holds the collection run.pvd"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("open " + (dir / "run" / "run.pvd").string()), std::string::npos)
      << r.output;
  // A folder without one says nothing of the kind.
  fs::remove(dir / "run" / "run.pvd");
  const auto plain =
      test::runSandstorm((dir / "run").string() + " --headless --frames 1 --set sim.maximum=500");
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  EXPECT_EQ(plain.output.find("holds the collection"), std::string::npos) << plain.output;
}

// A field read while the walls open (the first step comes 0.6 s after the
// run began to wait for it) moves the particles as one read before they open
// does. A wall waiting when the field is offered uploads it before packet 0
// (FrameChannel::offerField); one the main context beats to packet 0 (the
// offer is dropped then: a 4x4x4 field seeds in no time, and a loaded machine
// may not wake the wall first) uploads it with packet 0. Either way the
// particles are the same, and the run says which it was. (That an offered
// field reaches each waiting wall once: FrameChannel.AnOfferedFieldWakes...)
TEST(FieldStream, AFieldReadWhileTheWallsOpenDrawsWhatOneReadBeforeDoes) {
  const fs::path dir = test::scratchDir("field-stream-late");
  fs::create_directories(dir / "steps");
  const std::string args =
      "--config " + config(dir) + " --headless --frames 24 --log-level debug --hash-log ";
  std::atomic<bool> waiting{false};
  test::ProcessResult late;
  std::thread runner([&] {
    const std::string cmd = std::string("cd '") + SANDSTORM_SOURCE_DIR + "' && '" +
                            SANDSTORM_BINARY + "' " + args + (dir / "late.txt").string() + " 2>&1";
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return;
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe)) {
      late.output += buffer;
      if (late.output.find("for the first step in") != std::string::npos) waiting = true;
    }
    const int status = pclose(pipe);
    late.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    waiting = true;
  });
  for (int i = 0; i < 6000 && !waiting; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  writeVti(dir / "step.vti", wind({1, 0.5f, 0}));
  fs::rename(dir / "step.vti", dir / "steps" / "step_000.vti");  // complete at once
  runner.join();
  ASSERT_EQ(late.exitCode, 0) << late.output;
  EXPECT_NE(late.output.find("the walls open while the field is read"), std::string::npos)
      << late.output;
  const bool ahead = late.output.find("the field uploaded ahead of packet 0") != std::string::npos;
  std::printf("[ measured ] the field was uploaded %s\n",
              ahead ? "ahead of packet 0" : "with packet 0");
  const auto ready = test::runSandstorm(args + (dir / "ready.txt").string());
  ASSERT_EQ(ready.exitCode, 0) << ready.output;
  const std::vector<std::string> lines = test::readLines(dir / "late.txt");
  ASSERT_EQ(lines.size(), 24u);
  EXPECT_EQ(lines, test::readLines(dir / "ready.txt"));
}

}  // namespace
}  // namespace sandstorm
