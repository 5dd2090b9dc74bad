// The command line: help, bad arguments and bad files fail cleanly with a
// message and a non-zero exit; good runs write what they promise.
#include <gtest/gtest.h>

#include "tests/app/run_process.h"

namespace sandstorm {
namespace {

using test::runSandstorm;

TEST(CommandLine, HelpListsTheOptions) {
  const auto r = runSandstorm("--help");
  EXPECT_EQ(r.exitCode, 0);
  for (const char* option :
       {"--config", "--frames", "--screenshot", "--dump-particles", "--set", "--replay"})
    EXPECT_NE(r.output.find(option), std::string::npos) << option;
}

TEST(CommandLine, BadArgumentsFailWithAMessage) {
  struct Case {
    std::string args, expected;
  };
  for (const Case& c :
       {Case{"--frames -3", "--frames: expected a whole number, 0 or more; got '-3'"},
        Case{"--frames 3000000000", "--frames: expected at most 2147483647; got '3000000000'"},
        Case{"--screenshot-every many", "--screenshot-every: expected a whole number, 0 or more"},
        Case{"--config nowhere.toml", "nowhere.toml"}, Case{"--bogus", "unknown option '--bogus'"},
        // A mistyped option is named, with the one meant, not read as the field file.
        Case{"--screnshot 3", "unknown option '--screnshot' (did you mean '--screenshot'?)"},
        Case{"--frames=2 --movie-fsp=30",
             "unknown option '--movie-fsp' (did you mean '--movie-fps'?)"},
        Case{"--set render.size", "expected key=value"},
        Case{"--set render.sise=1", "unknown attribute 'render.sise'"},
        Case{"--set sim.integrator=rk3", "euler, rk2, rk4"},
        Case{"--set gpu.update_items=3", "--set gpu.update_items=3: gpu.update_items: expected"},
        Case{"--dump-particles out.txt", "expected a .vtp"},
        Case{"--walls nowhere", "no wall named 'nowhere'"},
        // Values that once meant "not given" are checked as any other.
        Case{"--movie /tmp/sandstorm-x.mp4 --movie-fps 0", "--movie-fps 0: expected 1 to 240"},
        Case{"--movie /tmp/sandstorm-x.mp4 --movie-crf -1", "--movie-crf -1: expected 0"},
        Case{"--movie-crf -1", "give --movie FILE too"}}) {
    const auto r = runSandstorm("--config tests/data/identity.toml --frames 1 " + c.args);
    EXPECT_NE(r.exitCode, 0) << c.args;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << " gave:\n" << r.output;
  }
}

TEST(CommandLine, BadConfigsNameTheirFileAndLine) {
  const auto dir = test::scratchDir("badconfig");
  std::ofstream(dir / "bad.toml") << "[[wall]]\nlower_left = [0, 0, 0]\nlower_right = [1, 0, 0]\n"
                                     "upper_left = [0, 0, 1]\nstereo = \"wiggle\"\n";
  const auto r = runSandstorm("--config " + (dir / "bad.toml").string());
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.output.find("bad.toml:5: wall[0].stereo"), std::string::npos) << r.output;
}

TEST(CommandLine, AWallOnAGpuThatIsNotThereIsAClearError) {
  // This machine's GPUs (llvmpipe's one, here) and round-robin over them draw
  // the same particles as every wall on GPU 0; a GPU beyond them stops the start.
  const auto dir = test::scratchDir("gpus");
  const std::string include =
      std::string("include = \"") + SANDSTORM_SOURCE_DIR + "/tests/data/identity.toml\"\n";
  std::ofstream(dir / "robin.toml") << include << "[run]\ngpus = \"round-robin\"\n";
  const auto first = runSandstorm("--config tests/data/identity.toml --frames 30 --hash-log " +
                                  (dir / "first.txt").string());
  const auto robin = runSandstorm("--config " + (dir / "robin.toml").string() +
                                  " --frames 30 --hash-log " + (dir / "robin.txt").string());
  ASSERT_EQ(first.exitCode, 0) << first.output;
  ASSERT_EQ(robin.exitCode, 0) << robin.output;
  EXPECT_EQ(test::readLines(dir / "first.txt"), test::readLines(dir / "robin.txt"));
  EXPECT_EQ(test::readLines(dir / "first.txt").size(), 4u * 30u);
  std::ofstream(dir / "far.toml")
      << "include = \"" << SANDSTORM_SOURCE_DIR << "/tests/data/identity.toml\"\n"
      << "[[wall]]\nname = \"far\"\nlower_left = [-1.5, 1.5, 0.0]\n"
      << "lower_right = [1.5, 1.5, 0.0]\nupper_left = [-1.5, 1.5, 3.0]\n"
      << "offscreen = { size = [64, 64] }\ngpu = 63\n";
  const auto far = runSandstorm("--config " + (dir / "far.toml").string() + " --frames 2");
  EXPECT_NE(far.exitCode, 0);
  EXPECT_NE(far.output.find("far.toml:2: wall 'far' on GPU 63: GPU 63 does not exist"),
            std::string::npos)
      << far.output;
  EXPECT_NE(far.output.find("expected gpu 0..0"), std::string::npos) << far.output;
}

TEST(CommandLine, WithoutOpenGL45TheMessageSaysWhatIsMissing) {
  // Mesa can be told to offer only OpenGL 3.3.
  const auto r =
      runSandstorm("--config tests/data/identity.toml --frames 1", "MESA_GL_VERSION_OVERRIDE=3.3");
  if (r.exitCode == 0 && r.output.find("Mesa") == std::string::npos)
    GTEST_SKIP() << "only Mesa can be told to offer less than OpenGL 4.5; this driver ran";
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.output.find("OpenGL 4.5"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Missing:"), std::string::npos) << r.output;
}

TEST(CommandLine, HeadlessRunsWriteImagesAndParticles) {
  const auto dir = test::scratchDir("outputs");
  const auto r = runSandstorm(
      "--config tests/data/identity.toml --frames 30 --walls front,left --screenshot " +
      dir.string() + " --dump-particles " + (dir / "p.vtp").string() +
      " --set emitter.0.rate=20000");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "front.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "left.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "right.png"));
  ASSERT_TRUE(std::filesystem::exists(dir / "p.vtp"));
  EXPECT_GT(std::filesystem::file_size(dir / "p.vtp"), 1000u);
  EXPECT_NE(r.output.find("stats:"), std::string::npos);
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

// Outputs that cannot be written: a missing folder, a folder where a file
// was named, an uncreatable folder and a full disk (/dev/full behind the
// name) each stop the run with an error naming the path; the paths that can
// be tried first are tried before anything runs.
TEST(CommandLine, OutputsThatCannotBeWrittenAreClearErrors) {
  const auto dir = test::scratchDir("unwritable-outputs");
  std::filesystem::create_directories(dir / "shots");
  std::filesystem::create_symlink("/dev/full", dir / "full.vtp");
  std::filesystem::create_symlink("/dev/full", dir / "full.session");
  std::filesystem::create_symlink("/dev/full", dir / "shots" / "front.png");
  const std::string run = "--config tests/data/identity.toml --walls front --frames 12 ";
  struct Case {
    std::string args, says;
    bool beforeTheRun;
  };
  const Case cases[] = {
      {"--dump-particles " + (dir / "missing" / "x.vtp").string(), "folder", true},
      {"--hash-log " + dir.string(), "is a folder; expected a file name", true},
      {"--screenshot /proc/sandstorm-cannot-be-here", "cannot make the folder", true},
      {"--dump-trails " + (dir / "missing" / "t.vtp").string(), "folder", true},
      {"--stats " + (dir / "missing" / "s.json").string(), "folder", true},
      {"--record " + (dir / "missing" / "r.session").string(), "folder", true},
      {"--dump-particles " + (dir / "full.vtp").string(), "writing failed", false},
      {"--screenshot " + (dir / "shots").string(), "No space left on device", false},
      {"--record " + (dir / "full.session").string(), "writing the session log failed", false},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    const auto r = runSandstorm(run + c.args);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("unexpected"), std::string::npos) << r.output;
    if (c.beforeTheRun) {
      EXPECT_EQ(r.output.find("wall 'front':"), std::string::npos) << r.output;
    }
  }
  // A field file is read only once the outputs and the session to replay are
  // known to be good (a large one takes minutes).
  std::ofstream(dir / "bad.session") << "garbage\n";
  for (const std::string& args : {"--dump-trails " + (dir / "missing" / "t.vtp").string(),
                                  "--replay " + (dir / "bad.session").string()}) {
    const auto r = runSandstorm("data/tornado.vti --frames 1 " + args);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_EQ(r.output.find("field: "), std::string::npos) << args << " gave:\n" << r.output;
  }
}

}  // namespace
}  // namespace sandstorm
