// The colour legend on its wall: run the app with and without it and look
// at what changed.
#include <gtest/gtest.h>

#include "core/color/color_map.h"
#include "core/util/image.h"
#include "tests/app/run_process.h"

namespace sandstorm {
namespace {

using test::runSandstorm;

bool near(glm::u8vec4 pixel, glm::vec3 color, float tolerance) {
  const glm::vec3 p = glm::vec3(glm::vec4(pixel)) / 255.0f;
  return glm::all(glm::lessThanEqual(glm::abs(p - color), glm::vec3(tolerance)));
}

TEST(Legend, TheMarkedWallShowsTheMapsColourBarInItsCornerAndNoOtherWallChanges) {
  const auto without = test::scratchDir("legend-off"), with = test::scratchDir("legend-on");
  const std::string run = "--config tests/data/legend.toml --screenshot ";
  const auto a = runSandstorm(run + without.string());
  ASSERT_EQ(a.exitCode, 0) << a.output;
  const auto b = runSandstorm(run + with.string() + " --set render.legend=true");
  ASSERT_EQ(b.exitCode, 0) << b.output;

  EXPECT_EQ(readPng(without / "front.png").rgba, readPng(with / "front.png").rgba)
      << "the legend belongs on 'left' only";
  const Image plain = readPng(without / "left.png"), legend = readPng(with / "left.png");
  ASSERT_EQ(plain.width, legend.width);
  const ColorMap viridis(ColorMapName::Viridis);
  int changed = 0, outsideCorner = 0;
  bool start = false, end = false;
  for (int y = 0; y < plain.height; ++y)
    for (int x = 0; x < plain.width; ++x) {
      if (plain.at(x, y) == legend.at(x, y)) continue;
      ++changed;
      if (x < plain.width / 5 || y < plain.height / 2) ++outsideCorner;
      start = start || near(legend.at(x, y), viridis.at(0.0f), 6.0f / 255.0f);
      end = end || near(legend.at(x, y), viridis.at(1.0f), 6.0f / 255.0f);
    }
  EXPECT_GT(changed, 500) << "no legend drawn";
  EXPECT_EQ(outsideCorner, 0) << "the legend sits in the lower right corner";
  EXPECT_TRUE(start) << "no pixel of the bar's low end (viridis 0)";
  EXPECT_TRUE(end) << "no pixel of the bar's high end (viridis 1)";
}
}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

// Trails and streamlines leave the run as .vtp polylines (the writer's own
// test reads them back with VTK).
TEST(FlowExport, TrailsAndStreamlinesAreWrittenAsPolylines) {
  const auto dir = test::scratchDir("flow-export");
  const auto r = runSandstorm(
      "--config tests/data/legend.toml --walls front --frames 12 "
      "--set render.trail_length=4 --set streamlines.enabled=true "
      "--dump-trails " +
      (dir / "trails.vtp").string() + " --dump-streamlines " + (dir / "lines.vtp").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* name : {"trails.vtp", "lines.vtp"}) {
    const std::string text = test::readBytes(dir / name);
    EXPECT_NE(text.find("<Lines>"), std::string::npos) << name;
    EXPECT_NE(text.find("Name=\"arc_length\""), std::string::npos) << name;
    EXPECT_EQ(text.find("NumberOfLines=\"0\""), std::string::npos) << name << ": no lines";
  }
  const auto bad = runSandstorm("--config tests/data/legend.toml --dump-trails " +
                                (dir / "trails.txt").string());
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.output.find("--dump-trails"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("expected a .vtp file name"), std::string::npos) << bad.output;
  const auto badLines = runSandstorm("--config tests/data/legend.toml --dump-streamlines " +
                                     (dir / "lines.csv").string());
  EXPECT_EQ(badLines.exitCode, 2);
  EXPECT_NE(badLines.output.find("--dump-streamlines"), std::string::npos) << badLines.output;
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

// render.color_range = particles: the main context turns the first wall's
// measurements into render.color_min/max changes; they are recorded, so a
// replay draws the same particles in the same colours without measuring.
TEST(AutoColorRange, TheMeasuredRangeIsRecordedAndReplaysBitForBit) {
  const auto dir = test::scratchDir("auto-range");
  const std::string run =
      "--config tests/data/legend.toml --frames 40 --set render.color_by=speed "
      "--set render.color_range=particles --set render.color_every=5 ";
  const auto recorded =
      runSandstorm(run + "--record " + (dir / "s.log").string() + " --hash-log " +
                   (dir / "a.txt").string() + " --screenshot " + (dir / "a").string());
  ASSERT_EQ(recorded.exitCode, 0) << recorded.output;
  int mins = 0, maxes = 0;
  for (const std::string& line : test::readLines(dir / "s.log")) {
    mins += line.find("render.color_min") != std::string::npos ? 1 : 0;
    maxes += line.find("render.color_max") != std::string::npos ? 1 : 0;
  }
  EXPECT_GE(mins, 2) << "the range follows the particles";
  EXPECT_EQ(mins, maxes);
  const auto replayed =
      runSandstorm(run + "--replay " + (dir / "s.log").string() + " --hash-log " +
                   (dir / "b.txt").string() + " --screenshot " + (dir / "b").string());
  ASSERT_EQ(replayed.exitCode, 0) << replayed.output;
  EXPECT_EQ(test::readLines(dir / "a.txt"), test::readLines(dir / "b.txt"));
  for (const char* wall : {"front.png", "left.png"})
    EXPECT_EQ(test::readBytes(dir / "a" / wall), test::readBytes(dir / "b" / wall)) << wall;
}

}  // namespace
}  // namespace sandstorm
