// Windows and the menu under Xvfb: four CAVE windows open, a slider dragged
// through the ImGui panel changes what every wall renders at the same frame,
// and closing a window or Ctrl-C stops everything cleanly with status 0.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <unistd.h>

#include "core/io/vti_writer.h"
#include "tests/app/run_process.h"
#include "tests/io/index_files.h"

namespace sandstorm {
namespace {

using test::haveXvfb;
using test::kXvfb;
using test::readLines;
using test::runSandstorm;
using test::runUnderXvfb;

struct Line {
  std::uint32_t frame;
  std::string wall, particles, state;
};

std::vector<Line> hashes(const std::filesystem::path& path) {
  std::vector<Line> out;
  for (const std::string& text : readLines(path)) {
    std::istringstream in(text);
    Line l;
    std::size_t count;
    in >> l.frame >> l.wall >> count >> l.particles >> l.state;
    out.push_back(l);
  }
  return out;
}

// 256^3 points of a field zlib compresses poorly: about 1.5 s to read here,
// 10 s to write, so the tests that read it share one file (written once,
// whole: it appears by a rename).
std::filesystem::path slowField() {
  const auto file = std::filesystem::temp_directory_path() / "sandstorm-test-slow-field-v1.vti";
  if (std::filesystem::exists(file)) return file;
  const int n = 256;
  std::vector<glm::vec3> values(std::size_t(n) * n * n);
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = glm::vec3(std::sin(0.37f * float(i % 977)), std::cos(0.011f * float(i % 6151)),
                          0.001f * float(i % 4093));
  const auto part = file.string() + "." + std::to_string(::getpid()) + ".vti";
  writeVti(part, VectorField(Box{{0, 0, 0}, {4, 4, 4}}, glm::ivec3(n), std::move(values)));
  std::filesystem::rename(part, file);
  return file;
}

// `sandstorm FILE` with a file that takes a while to read. A multiblock file
// (.vtm) is read before the walls open, so it shows its progress in a window
// first (the bar and, in the title, the log's line). A .vti is framed from its
// header and read while the walls open, whose windows show its bar. Without
// windows neither says so, and the .vti is read while the walls open.
TEST(Windows, AFileTakingAWhileToReadShowsItsProgressInAWindowOrOnTheWalls) {
  if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed (scripts/setup installs it)";
  const auto dir = test::scratchDir("loading-window");
  std::filesystem::create_symlink(slowField(), dir / "big.vti");
  test::writeVtmFor(dir / "big.vti", dir / "big.vtm");
  const std::string options =
      " --frames 2 --set sim.maximum=1000 --log-level debug --screenshot '" + dir.string() + "'";
  const auto first = runUnderXvfb("'" + (dir / "big.vtm").string() + "'" + options);
  ASSERT_EQ(first.exitCode, 0) << first.output;
  const std::size_t loading = first.output.find("loading: the progress shows in a window too");
  const std::size_t walls = first.output.find("GLFW window 'Sandstorm: desktop'");
  ASSERT_NE(loading, std::string::npos) << first.output;
  ASSERT_NE(walls, std::string::npos) << first.output;
  EXPECT_LT(loading, walls);

  const std::string vti = "'" + (dir / "big.vti").string() + "'" + options;
  const auto framed = runUnderXvfb(vti);
  ASSERT_EQ(framed.exitCode, 0) << framed.output;
  const std::size_t window = framed.output.find("GLFW window 'Sandstorm: desktop'");
  const std::size_t read = framed.output.find("field: " + (dir / "big.vti").string());
  ASSERT_NE(window, std::string::npos) << framed.output;
  ASSERT_NE(read, std::string::npos) << framed.output;
  EXPECT_LT(window, read);
  EXPECT_NE(framed.output.find("loading: the progress shows on the walls"), std::string::npos)
      << framed.output;
  EXPECT_NE(
      framed.output.find("wall 'desktop' showed the loading's progress until its first frame"),
      std::string::npos)
      << framed.output;

  const auto headless = runSandstorm(vti + " --headless");
  ASSERT_EQ(headless.exitCode, 0) << headless.output;
  EXPECT_EQ(headless.output.find("loading: the progress"), std::string::npos) << headless.output;
  EXPECT_NE(headless.output.find("the walls open while the field is read"), std::string::npos)
      << headless.output;
}

// A configuration's field that takes a while to read: the walls' windows
// open while it is read and show its progress until their first frame.
// (That a field read while the walls open draws what one read before does:
// FieldStream.AFieldReadWhileTheWallsOpenDrawsWhatOneReadBeforeDoes.)
TEST(Windows, TheWallsWindowsOpenWhileTheFieldIsReadAndShowItsProgress) {
  if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed (scripts/setup installs it)";
  const auto dir = test::scratchDir("loading-walls");
  std::filesystem::create_symlink(slowField(), dir / "big.vti");
  {
    std::ofstream config(dir / "slow.toml");
    config << "include = \""
           << (std::filesystem::path(SANDSTORM_SOURCE_DIR) / "tests/data/windows.toml").string()
           << "\"\n[field]\nsource = \"big.vti\"\n";
  }
  const std::string args = "--config '" + (dir / "slow.toml").string() +
                           "' --frames 6 --set sim.maximum=2000 --log-level debug --hash-log '";
  const auto shown = runUnderXvfb(args + (dir / "windows.txt").string() + "'");
  ASSERT_EQ(shown.exitCode, 0) << shown.output;
  const std::size_t window = shown.output.find("GLFW window 'Sandstorm: front'");
  const std::size_t overlap = shown.output.find("the walls open while the field is read");
  const std::size_t loading = shown.output.find("loading: the progress shows on the walls");
  const std::size_t read = shown.output.find("field: " + (dir / "big.vti").string());
  ASSERT_NE(window, std::string::npos) << shown.output;
  ASSERT_NE(overlap, std::string::npos) << shown.output;
  ASSERT_NE(loading, std::string::npos) << shown.output;
  ASSERT_NE(read, std::string::npos) << shown.output;
  EXPECT_LT(window, read);  // the walls opened before the field was read
  for (const char* wall : {"left", "front", "right", "floor"})
    EXPECT_NE(shown.output.find(std::string("wall '") + wall +
                                "' showed the loading's progress until its first frame"),
              std::string::npos)
        << wall << "\n"
        << shown.output;
  // Every wall drew every frame.
  EXPECT_EQ(readLines(dir / "windows.txt").size(), 6u * 4u);
}

TEST(Windows, ASliderInTheMenuChangesEveryWallAtTheSameFrame) {
  if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed (scripts/setup installs it)";
  const auto dir = test::scratchDir("menu");
  const auto r = runUnderXvfb(
      "--config tests/data/windows.toml --menu-script tests/data/slider.script --record " +
      (dir / "s.session").string() + " --hash-log " + (dir / "h.txt").string() + " --screenshot " +
      dir.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* wall : {"left", "front", "right", "floor"})
    EXPECT_NE(r.output.find(std::string("GLFW window 'Sandstorm: ") + wall), std::string::npos)
        << wall;

  // The click went through ImGui into the main context, which recorded it with its frame.
  std::uint32_t sizeFrame = 0, pauseFrame = 0;
  for (const std::string& line : readLines(dir / "s.session")) {
    std::istringstream in(line);
    std::uint32_t f;
    std::string verb, key;
    if (!(in >> f >> verb >> key)) continue;
    if (key == "render.size") sizeFrame = f;
    if (key == "sim.paused") pauseFrame = f;
  }
  ASSERT_GT(sizeFrame, 0u) << "the slider click did not change render.size";
  ASSERT_GT(pauseFrame, sizeFrame) << "the pause button did not take";

  // Every wall's replica changed at exactly that frame, and the walls agree on the particles.
  std::map<std::string, std::map<std::uint32_t, Line>> byWall;
  for (const Line& l : hashes(dir / "h.txt"))
    byWall[l.wall][l.frame] = l;
  ASSERT_EQ(byWall.size(), 4u);
  for (auto& [wall, frames] : byWall) {
    for (std::uint32_t f = 1; f < 40; ++f) {
      const bool changed = frames[f].state != frames[f - 1].state;
      EXPECT_EQ(changed, f == sizeFrame || f == pauseFrame) << wall << " frame " << f;
      EXPECT_EQ(frames[f].particles, byWall["front"][f].particles) << wall << " frame " << f;
      if (f > pauseFrame) {
        EXPECT_EQ(frames[f].particles, frames[f - 1].particles) << "paused, yet moving";
      }
    }
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "front.png"));
}

// The menu's Obstacles section (config/obstacle.toml, the Mali scene, in a
// window): a click opens it, a click on the radius slider changes obstacle 0
// at a frame the session records.
TEST(Windows, TheObstaclesSectionOfTheMenuMovesTheSphere) {
  if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed (scripts/setup installs it)";
  const auto dir = test::scratchDir("menu-obstacles");
  const auto r = runUnderXvfb(
      "--config config/obstacle.toml --frames 40 --menu-script tests/data/obstacle-menu.script "
      "--record " +
      (dir / "s.session").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::string radius;
  int moves = 0;
  for (const std::string& line : readLines(dir / "s.session")) {
    if (line.find(" set obstacle.0.radius ") != std::string::npos) radius = line;
    moves += line.find(" set obstacle.0.position ") != std::string::npos;
  }
  ASSERT_FALSE(radius.empty()) << "the slider click did not change obstacle.0.radius\n" << r.output;
  EXPECT_NE(radius.substr(radius.rfind(' ') + 1), "0.55");  // the file's radius changed
  EXPECT_GE(moves, 38);  // and the sphere moved along its path every frame
}

// The field editor's section: open it, pick slot 1 (the vortex), drag its
// strength slider: the change is recorded and the composed field follows it.
TEST(Windows, TheFieldEditorSectionChangesAPrimitive) {
  if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed (scripts/setup installs it)";
  const auto dir = test::scratchDir("menu-editor");
  const auto r = runUnderXvfb(
      "--config config/field-editor.toml --frames 40 --set sim.maximum=4000 --log-level debug "
      "--menu-script tests/data/editor-menu.script --record " +
      (dir / "s.session").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::string strength;
  for (const std::string& line : readLines(dir / "s.session"))
    if (line.find(" set primitive.1.strength ") != std::string::npos) strength = line;
  ASSERT_FALSE(strength.empty()) << "the slider click did not change primitive.1.strength\n"
                                 << r.output;
  EXPECT_NE(strength.substr(strength.rfind(' ') + 1), "1.6");  // the file's strength changed
  // Composed twice: at the start, and after the change.
  std::size_t composed = 0;
  for (std::size_t at = r.output.find("field editor: 3 primitive(s)"); at != std::string::npos;
       at = r.output.find("field editor: 3 primitive(s)", at + 1))
    ++composed;
  EXPECT_EQ(composed, 2u) << r.output;
}

TEST(Windows, TheMoleculesSectionOfTheMenuChangesTheirShapeAndSprings) {
  if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed (scripts/setup installs it)";
  const auto dir = test::scratchDir("menu-molecules");
  const auto r = runUnderXvfb(
      "--config config/molecules.toml --frames 40 --set sim.maximum=4000 "
      "--set molecules.maximum=800 --menu-script tests/data/molecule-menu.script --record " +
      (dir / "s.session").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::string complexity, stiffness;
  for (const std::string& line : readLines(dir / "s.session")) {
    if (line.find(" set molecules.complexity ") != std::string::npos) complexity = line;
    if (line.find(" set molecules.stiffness ") != std::string::npos) stiffness = line;
  }
  ASSERT_FALSE(complexity.empty()) << "the slider click did not change molecules.complexity\n"
                                   << r.output;
  EXPECT_NE(complexity.substr(complexity.rfind(' ') + 1), "4");  // the file's complexity changed
  ASSERT_FALSE(stiffness.empty()) << r.output;
  EXPECT_NE(stiffness.substr(stiffness.rfind(' ') + 1), "0.8");
}

TEST(Windows, FourWindowsCanShareOneSimulation) {
  if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed (scripts/setup installs it)";
  const auto dir = test::scratchDir("shared-windows");
  const auto own = runUnderXvfb("--config tests/data/windows.toml --no-menu --hash-log " +
                                (dir / "own.txt").string());
  const auto shared = runUnderXvfb("--config tests/data/windows-shared.toml --no-menu --hash-log " +
                                   (dir / "shared.txt").string());
  ASSERT_EQ(own.exitCode, 0) << own.output;
  ASSERT_EQ(shared.exitCode, 0) << shared.output;
  const auto a = hashes(dir / "own.txt"), b = hashes(dir / "shared.txt");
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.size(), 4u * 40u);
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_EQ(a[i].particles, b[i].particles) << a[i].wall << " " << a[i].frame;
}

TEST(Windows, TheMenuCanLiveInAnOperatorWindowOfItsOwn) {
  if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed (scripts/setup installs it)";
  const auto dir = test::scratchDir("operator");
  const auto r = runUnderXvfb(
      "--config tests/data/operator.toml --menu-script tests/data/slider.script --record " +
      (dir / "s.session").string() + " --hash-log " + (dir / "h.txt").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  bool sized = false;
  for (const std::string& line : readLines(dir / "s.session"))
    sized = sized || line.find("render.size") != std::string::npos;
  EXPECT_TRUE(sized) << "the click in the operator window did not change render.size";
  // The walls stay offscreen: the operator window is the only window.
  EXPECT_EQ(r.output.find("GLFW window"), std::string::npos) << r.output;
}

TEST(Windows, AMonitorThatDoesNotExistStopsEverythingBeforeAnyWindowOpens) {
  if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed (scripts/setup installs it)";
  // cave4.toml puts its walls on monitors 0-3; Xvfb has one.
  const auto r = runUnderXvfb("--config config/cave4.toml --frames 1");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(
      r.output.find(
          "config/cave4.toml:28: wall[1].window.monitor: monitor 1 does not exist; 1 connected"),
      std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("GLFW window"), std::string::npos) << "a window opened before the check";
}

TEST(Windows, ClosingAWindowStopsEveryWallCleanly) {
  if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed (scripts/setup installs it)";
  const auto r = runUnderXvfb(
      "--config tests/data/windows.toml --frames 0 --menu-script tests/data/close.script");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("a window closed: stopped every wall cleanly"), std::string::npos)
      << r.output;
}

TEST(Windows, CtrlCStopsEveryWallCleanly) {
  if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed (scripts/setup installs it)";
  // The shell under xvfb-run starts sandstorm, interrupts it once it is drawing, and passes on its
  // status.
  const auto dir = test::scratchDir("interrupt");
  const std::string log = (dir / "log.txt").string();
  const auto script = dir / "interrupt.sh";
  std::ofstream(script) << "'" SANDSTORM_BINARY
                           "' --config tests/data/windows.toml --frames 0 --no-menu > '"
                        << log << "' 2>&1 &\np=$!\nfor i in $(seq 150); do grep -q 'frame ' '"
                        << log << "' && break; sleep 0.2; done\nkill -INT $p\nwait $p\n";
  const std::string cmd =
      "cd '" SANDSTORM_SOURCE_DIR "' && " + kXvfb + "sh '" + script.string() + "'";
  const int status = std::system(cmd.c_str());
  const std::string output = [&] {
    std::string all;
    for (const std::string& l : readLines(log))
      all += l + "\n";
    return all;
  }();
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 0) << output;
  EXPECT_NE(output.find("interrupted: stopped every wall cleanly"), std::string::npos) << output;
}

}  // namespace
}  // namespace sandstorm
