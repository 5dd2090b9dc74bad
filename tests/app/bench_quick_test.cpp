// sandstorm-bench --quick: runs in seconds on llvmpipe and produces the table
// and the JSON with every section and stage. Structure only: no timing is
// asserted (speed belongs in the benchmark, not in tests).
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "tests/app/run_process.h"

namespace sandstorm {
namespace {

test::ProcessResult runBench(const std::string& args) {
  return test::runCommand(std::string("'") + SANDSTORM_BENCH + "' " + args + " 2>&1");
}

// The value of "key": "..." or "key": number in one JSON row line.
std::string field(const std::string& line, const std::string& key) {
  const std::string tag = "\"" + key + "\": ";
  const auto at = line.find(tag);
  if (at == std::string::npos) return "<missing>";
  auto from = at + tag.size();
  if (line[from] == '"') {
    const auto to = line.find('"', from + 1);
    return line.substr(from + 1, to - from - 1);
  }
  const auto to = line.find_first_of(",}", from);
  return line.substr(from, to - from);
}

TEST(BenchQuick, PrintsTheTableAndWritesEverySectionToJson) {
  const auto dir = test::scratchDir("bench");
  const auto json = dir / "bench.json";
  const test::ProcessResult r = runBench("--quick --json '" + json.string() + "'");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  // Progress, the table and the targets.
  EXPECT_NE(r.output.find("[1/"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("ratio to ceiling"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Targets"), std::string::npos) << r.output;

  const auto lines = test::readLines(json);
  ASSERT_FALSE(lines.empty());
  std::set<std::string> seen;
  int rows = 0;
  for (const std::string& line : lines) {
    if (line.find("\"section\"") == std::string::npos) continue;
    ++rows;
    const std::string section = field(line, "section"), stage = field(line, "stage");
    seen.insert(section + "/" + stage);
    for (const char* key : {"backend", "field", "renderer", "sim", "particles", "walls", "gpu_ms",
                            "particles_per_s", "bytes_per_s", "ceiling", "ratio", "wall_clock_ms"})
      EXPECT_NE(field(line, key), "<missing>") << key << " in " << line;
    EXPECT_GE(std::stod(field(line, "gpu_ms")), 0.0) << line;
    if (section == "update") {
      // Every update row says what it is compared with.
      EXPECT_TRUE(field(line, "ceiling") == "copy" || field(line, "ceiling") == "bare-tf") << line;
      EXPECT_GT(std::stod(field(line, "particles")), 0.0) << line;
    }
  }
  for (const char* expected :
       {"verify/agreement", "ceilings/copy", "ceilings/bare-tf", "ceilings/bare-points",
        "update/update", "render/scene", "render/particles", "render/post", "walls/update",
        "walls/views", "walls/frame", "sort/sort"})
    EXPECT_TRUE(seen.count(expected)) << expected;
  // 2 verify; 2 copies + 3 ceilings x 2 counts; 2 particle counts x 2 backends x 2 fields of
  // updates; 4 renderers x 2 counts x 3 stages; 2 wall counts x 2 sims x 2 renderers x 3 stages.
  EXPECT_GE(rows, 2 + 2 + 6 + 8 + 24 + 2 * 2 * 2 * 3);
  for (const char* key : {"\"device\"", "\"command\"", "\"copy_bytes_per_s\""})
    EXPECT_NE(lines[1].find(key) == std::string::npos && lines[2].find(key) == std::string::npos &&
                  lines[3].find(key) == std::string::npos,
              true)
        << key;
}

TEST(BenchQuick, RefusesUnknownOptions) {
  const test::ProcessResult r = runBench("--quick --renderers sprites");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.output.find("unknown 'sprites'"), std::string::npos) << r.output;
  const test::ProcessResult t = runBench("--quick --wall-trails 0,65");
  EXPECT_NE(t.exitCode, 0);
  EXPECT_NE(t.output.find("--wall-trails: 65: expected a trail length of 0 to 64"),
            std::string::npos)
      << t.output;
}

// The walls section with and without trails and shadows: a row of each, the
// trail length and the shadows in it.
TEST(BenchQuick, TheWallsSectionMeasuresFramesWithTrailsAndShadows) {
  const auto dir = test::scratchDir("bench-trails");
  const auto json = dir / "bench.json";
  const test::ProcessResult r = runBench(
      "--quick --sections walls --walls 1 --wall-sims shared --wall-renderers splat "
      "--wall-trails 0,8 --wall-shadows 0,1 --json '" +
      json.string() + "'");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::set<std::string> rows;
  for (const std::string& line : test::readLines(json))
    if (line.find("\"stage\": \"frame\"") != std::string::npos)
      rows.insert(field(line, "trails") + "/" + field(line, "shadows"));
  EXPECT_EQ(rows, (std::set<std::string>{"0/false", "0/true", "8/false", "8/true"}));
  EXPECT_NE(r.output.find("trails 8, shadows on:"), std::string::npos) << r.output;
}

// The update section without obstacles, with a sphere and with a sphere and
// a box: a row of each per backend, and the comparisons in the targets.
TEST(BenchQuick, TheUpdateSectionMeasuresTheObstacleTerm) {
  const auto dir = test::scratchDir("bench-obstacles");
  const auto json = dir / "bench.json";
  const test::ProcessResult r =
      runBench("--quick --sections update --fields texture --update-obstacles 0,1,2 --json '" +
               json.string() + "'");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::set<std::string> rows;
  for (const std::string& line : test::readLines(json))
    if (line.find("\"stage\": \"update\"") != std::string::npos)
      rows.insert(field(line, "backend") + "/" + field(line, "obstacles"));
  EXPECT_EQ(rows, (std::set<std::string>{"compute/0", "compute/1", "compute/2", "tf-gs/0",
                                         "tf-gs/1", "tf-gs/2"}));
  EXPECT_NE(r.output.find("tf-gs update with a sphere,"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("compute update with a sphere and a box,"), std::string::npos)
      << r.output;
  EXPECT_NE(runBench("--quick --update-obstacles 3").output.find("expected 0 (none), 1"),
            std::string::npos);
}

TEST(BenchQuick, TheSolverSectionStepsTheFlowOnTheGpu) {
  const auto dir = test::scratchDir("bench-solver");
  const auto json = dir / "bench.json";
  const test::ProcessResult r = runBench(
      "--quick --sections solver --solver-grids 12x10x6,16x16x8 --json '" + json.string() + "'");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  int rows = 0;
  for (const std::string& line : test::readLines(json))
    rows += line.find("\"section\": \"solver\"") != std::string::npos;
  EXPECT_EQ(rows, 2);
  EXPECT_NE(r.output.find("16x16x8: "), std::string::npos) << r.output;
  EXPECT_NE(runBench("--quick --solver-grids 1x8x8").output.find("expected 2..1024 cells"),
            std::string::npos);
}

TEST(BenchQuick, TheUpdateSectionMeasuresMoleculesAgainstParticles) {
  const auto dir = test::scratchDir("bench-molecules");
  const auto json = dir / "bench.json";
  const test::ProcessResult r = runBench(
      "--quick --sections update --backends compute --fields texture "
      "--update-molecules 0,4 --json '" +
      json.string() + "'");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::set<std::string> rows;
  for (const std::string& line : test::readLines(json))
    if (line.find("\"stage\": \"update\"") != std::string::npos)
      rows.insert(field(line, "molecules") + "/" + field(line, "particles"));
  // As many particles in molecules of 4 as alone: the molecules all lived.
  EXPECT_EQ(rows, (std::set<std::string>{"0/1000", "0/4000", "4/1000", "4/4000"}));
  EXPECT_NE(r.output.find("update of molecules of 4"), std::string::npos) << r.output;
  EXPECT_NE(runBench("--quick --update-molecules 1").output.find("a complexity of 2 to 8"),
            std::string::npos);
}

}  // namespace
}  // namespace sandstorm
