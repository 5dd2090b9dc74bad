// The run's statistics (--stats FILE.json, app/run_stats.h): the frames after
// run.stats_warmup are measured on every wall, every stage has a GPU time, and
// the live particles reported are a frame or two old (read without waiting
// for the GPU), which the hash log's exact counts pin down.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <sstream>

#include "tests/app/run_process.h"

namespace sandstorm {
namespace {

// The value of "key": number in `text` from `from` on.
double field(const std::string& text, const std::string& key, std::size_t from = 0) {
  std::smatch m;
  const std::string rest = text.substr(from);
  if (!std::regex_search(rest, m, std::regex("\"" + key + "\": ([-0-9.e+]+)")))
    ADD_FAILURE() << "no " << key << " in " << rest;
  return m.empty() ? -1.0 : std::stod(m[1]);
}

TEST(RunStats, TheFramesAfterTheWarmupAreMeasuredOnEveryWall) {
  const auto dir = test::scratchDir("run-stats");
  const auto r = test::runSandstorm("--config tests/data/identity.toml --frames 100 --stats " +
                                    (dir / "stats.json").string() + " --hash-log " +
                                    (dir / "hashes.txt").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("frame times over 40 frames after 60"), std::string::npos) << r.output;
  const std::string json = test::readBytes(dir / "stats.json");
  EXPECT_EQ(field(json, "warmup_frames"), 60.0);
  EXPECT_EQ(field(json, "frames"), 40.0);
  EXPECT_GT(field(json, "frame_ms_median"), 0.0);
  // The exact count of each wall at each frame.
  std::map<std::string, std::map<int, double>> counts;
  for (const std::string& line : test::readLines(dir / "hashes.txt")) {
    std::istringstream in(line);
    int frame = 0;
    std::string wall;
    double count = 0;
    in >> frame >> wall >> count;
    counts[wall][frame] = count;
  }
  for (const char* wall : {"front", "left", "right", "floor"}) {
    SCOPED_TRACE(wall);
    const std::size_t at = json.find(std::string("\"name\": \"") + wall + "\"");
    ASSERT_NE(at, std::string::npos) << json;
    EXPECT_NE(json.substr(at, 60).find("\"renderer\": \"billboards\""), std::string::npos) << json;
    EXPECT_EQ(field(json, "frames", at), 40.0);
    for (const char* stage : {"update_ms", "scene_ms", "particles_ms", "post_ms", "gpu_ms"})
      EXPECT_GT(field(json, stage, at), 0.0) << stage;
    const double live = field(json, "live_particles", at);
    EXPECT_TRUE(live == counts[wall][97] || live == counts[wall][98])
        << live << " live; the counts at frames 97, 98, 99: " << counts[wall][97] << ", "
        << counts[wall][98] << ", " << counts[wall][99];
  }
}

// A run no longer than run.stats_warmup (60 here) measures its second half,
// and says so, rather than reporting nothing.
TEST(RunStats, ARunShorterThanTheWarmupMeasuresItsSecondHalf) {
  const auto dir = test::scratchDir("run-stats-short");
  const auto r = test::runSandstorm("--config tests/data/identity.toml --frames 50 --stats " +
                                    (dir / "stats.json").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("leave out its first 25 instead"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("frame times over 25 frames after 25"), std::string::npos) << r.output;
  const std::string json = test::readBytes(dir / "stats.json");
  EXPECT_EQ(field(json, "warmup_frames"), 25.0);
  EXPECT_EQ(field(json, "frames"), 25.0);
  EXPECT_GT(field(json, "frame_ms_median"), 0.0);
}

}  // namespace
}  // namespace sandstorm
