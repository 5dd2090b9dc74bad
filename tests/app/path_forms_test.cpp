// Every way a user names a file works (issue: `cd config && sandstorm
// --config desktop.toml` once stopped at "cannot make absolute path"): a bare
// name in the folder one stands in, a relative path, an absolute one, a
// symbolic link to a configuration (whose own relative paths then start at the
// real file's folder), a field path inside a configuration relative to that
// configuration wherever one starts, and a field file given bare; for
// --config, the field, --record, --replay, --screenshot, --dump-particles,
// --stats and the tracker simulator's --path.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/app/run_process.h"

namespace sandstorm {
namespace {

namespace fs = std::filesystem;

// Runs sandstorm with `args` from the folder `cwd`.
test::ProcessResult runIn(const fs::path& cwd, const std::string& args) {
  return test::runCommand("cd '" + cwd.string() + "' && '" + SANDSTORM_BINARY + "' " + args +
                          " 2>&1");
}

const std::string kQuick = " --headless --frames 3 ";

TEST(PathForms, ABareRelativeAbsoluteOrLinkedConfigAndItsOutputsAllWork) {
  const fs::path dir = test::scratchDir("path-forms");
  const fs::path source = SANDSTORM_SOURCE_DIR;
  // A configuration of one's own in a folder of one's own.
  std::ofstream(dir / "mine.toml")
      << "include = \"" << (source / "tests/data/identity.toml").string() << "\"\n";
  // Bare names, standing in that folder.
  auto r = runIn(dir, "--config mine.toml" + kQuick +
                          "--record session.log --stats stats.json --dump-particles last.vtp "
                          "--screenshot shots");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* made : {"session.log", "stats.json", "last.vtp"})
    EXPECT_TRUE(fs::exists(dir / made)) << made << "\n" << r.output;
  EXPECT_FALSE(fs::is_empty(dir / "shots")) << r.output;
  r = runIn(dir, "--config mine.toml --headless --replay session.log --hash-log replayed.txt");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "replayed.txt"));

  // Relative to a parent folder, and absolute.
  const std::string name = dir.filename().string();
  r = runIn(dir.parent_path(),
            "--config " + name + "/mine.toml" + kQuick + "--stats " + name + "/relative.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "relative.json"));
  r = runIn("/", "--config " + (dir / "mine.toml").string() + kQuick + "--stats " +
                     (dir / "absolute.json").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "absolute.json"));

  // A symbolic link to a configuration whose include is relative to its real folder.
  fs::create_directories(dir / "links");
  fs::create_symlink(source / "tests/data/identity.toml", dir / "links" / "linked.toml");
  r = runIn(dir, "--config links/linked.toml" + kQuick);
  EXPECT_EQ(r.exitCode, 0) << r.output;
}

TEST(PathForms, AFieldInAConfigIsRelativeToItAndAFieldFileMayBeGivenBare) {
  const fs::path dir = test::scratchDir("path-forms-field");
  const fs::path source = SANDSTORM_SOURCE_DIR;
  fs::create_directories(dir / "data");
  fs::copy_file(source / "data/tornado.vti", dir / "data/tornado.vti");
  std::ofstream(dir / "field.toml")
      << "include = \"" << (source / "tests/data/identity.toml").string()
      << "\"\n[field]\nsource = \"data/tornado.vti\"\n";
  // From anywhere: the field is found beside the configuration.
  auto r = runIn("/", "--config " + (dir / "field.toml").string() + kQuick);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("tornado.vti"), std::string::npos) << r.output;
  // The field file itself, bare, standing beside it.
  r = runIn(dir / "data", "tornado.vti" + kQuick + "--stats bare.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "data/bare.json"));
}

TEST(PathForms, TheTrackerSimulatorTakesABarePathFile) {
  const fs::path dir = test::scratchDir("path-forms-tracker");
  std::ofstream(dir / "walk.toml") << "loop = false\n[[key]]\ntime = 0.0\nhead = [0.0, 0.0, 1.7]\n";
  const auto r = test::runCommand("cd '" + dir.string() + "' && '" + SANDSTORM_TRACKER_SIM +
                                  "' --port 9 --rate 50 --duration 0.1 --path walk.toml 2>&1");
  EXPECT_EQ(r.exitCode, 0) << r.output;
}

}  // namespace
}  // namespace sandstorm
