// Split first, proven: four walls, each with its own GL context on its own
// thread, hold bitwise identical particle buffers at every one of 200 frames
// (emission, death and mid-run changes included); so do four processes with
// one wall each, and four walls drawn in turn from one context; and a recorded
// session replays to the same particles. The shadows they cast agree too.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include "core/field/vortex_field.h"
#include "core/io/field_writer.h"
#include "tests/app/run_process.h"

namespace sandstorm {
namespace {

using test::readLines;
using test::runSandstorm;

struct HashLine {
  std::uint32_t frame;
  std::string wall;
  std::size_t count;
  std::string hash;
};

std::vector<HashLine> readHashes(const std::filesystem::path& path) {
  std::vector<HashLine> out;
  for (const std::string& line : readLines(path)) {
    std::istringstream in(line);
    HashLine h;
    in >> h.frame >> h.wall >> h.count >> h.hash;
    out.push_back(h);
  }
  return out;
}

const std::string kRun = "--config tests/data/identity.toml --replay tests/data/midrun.session ";

TEST(Identity, FourWallsOnFourThreadsHoldTheSameParticlesEveryFrame) {
  const auto dir = test::scratchDir("threads");
  const auto r = runSandstorm(kRun + "--hash-log " + (dir / "all.txt").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::vector<HashLine> lines = readHashes(dir / "all.txt");
  ASSERT_EQ(lines.size(), 4u * 200u);
  std::map<std::uint32_t, std::set<std::string>> hashesPerFrame;
  std::map<std::uint32_t, std::size_t> counts;
  for (const HashLine& h : lines) {
    hashesPerFrame[h.frame].insert(h.hash);
    counts[h.frame] = h.count;
  }
  for (const auto& [frame, hashes] : hashesPerFrame)
    EXPECT_EQ(hashes.size(), 1u) << "walls differ at frame " << frame;
  // The run had births, deaths and the mid-run change: the count rises, then
  // turns over, and the frame-90 change (more, shorter-lived particles) shows.
  EXPECT_GT(counts[60], 5000u);
  EXPECT_NE(counts[120], counts[89]);
  std::set<std::string> distinct;
  for (const auto& [frame, hashes] : hashesPerFrame)
    distinct.insert(*hashes.begin());
  EXPECT_EQ(distinct.size(), 200u);  // every frame's particles differ from every other's
}

TEST(Identity, OneWallPerProcessMatchesAllWallsInOne) {
  const auto dir = test::scratchDir("processes");
  const auto all = runSandstorm(kRun + "--frames 120 --hash-log " + (dir / "all.txt").string());
  ASSERT_EQ(all.exitCode, 0) << all.output;
  std::map<std::string, std::vector<std::string>> perWall;
  for (const HashLine& h : readHashes(dir / "all.txt"))
    perWall[h.wall].push_back(h.hash);
  for (const std::string wall : {"front", "floor"}) {
    const auto log = dir / (wall + ".txt");
    const auto one =
        runSandstorm(kRun + "--frames 120 --walls " + wall + " --hash-log " + log.string());
    ASSERT_EQ(one.exitCode, 0) << one.output;
    std::vector<std::string> hashes;
    for (const HashLine& h : readHashes(log))
      hashes.push_back(h.hash);
    EXPECT_EQ(hashes, perWall[wall]) << wall;
  }
}

TEST(Identity, OneSimulationPerGpuMatchesOnePerWall) {
  // run.shared_simulation: one wall updates, three draw its buffers through shared contexts.
  const auto dir = test::scratchDir("shared");
  const auto own = runSandstorm(kRun + "--frames 150 --hash-log " + (dir / "own.txt").string() +
                                " --screenshot " + (dir / "own").string());
  const auto shared = runSandstorm(
      "--config tests/data/identity-shared.toml --replay tests/data/midrun.session "
      "--frames 150 --hash-log " +
      (dir / "shared.txt").string() + " --screenshot " + (dir / "shared").string());
  ASSERT_EQ(own.exitCode, 0) << own.output;
  ASSERT_EQ(shared.exitCode, 0) << shared.output;
  const std::vector<HashLine> a = readHashes(dir / "own.txt"), b = readHashes(dir / "shared.txt");
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].hash, b[i].hash) << a[i].wall << " frame " << a[i].frame;
    EXPECT_EQ(a[i].count, b[i].count);
  }
  for (const char* wall : {"front", "left", "right", "floor"}) {
    const auto read = [](const std::filesystem::path& p) {
      std::ifstream in(p, std::ios::binary);
      return std::string(std::istreambuf_iterator<char>(in), {});
    };
    EXPECT_EQ(read(dir / "own" / (std::string(wall) + ".png")),
              read(dir / "shared" / (std::string(wall) + ".png")))
        << wall << ": the images differ";
  }
}

TEST(Identity, WallsDrawnFromOneContextMatchWallsOnTheirOwnThreads) {
  // run.offscreen_contexts = "one": one thread draws the four walls in turn.
  const auto dir = test::scratchDir("one-context");
  const std::string args = " --replay tests/data/midrun.session --frames 120 --hash-log ";
  const auto threads =
      runSandstorm("--config tests/data/identity-shared.toml" + args +
                   (dir / "threads.txt").string() + " --screenshot " + (dir / "threads").string());
  const auto one =
      runSandstorm("--config tests/data/identity-one-context.toml" + args +
                   (dir / "one.txt").string() + " --screenshot " + (dir / "one").string());
  ASSERT_EQ(threads.exitCode, 0) << threads.output;
  ASSERT_EQ(one.exitCode, 0) << one.output;
  EXPECT_NE(one.output.find("(the context of wall 'front')"), std::string::npos) << one.output;
  EXPECT_EQ(threads.output.find("(the context of wall"), std::string::npos) << threads.output;
  const std::vector<HashLine> a = readHashes(dir / "threads.txt"), b = readHashes(dir / "one.txt");
  ASSERT_EQ(a.size(), 4u * 120u);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_EQ(a[i].hash, b[i].hash) << a[i].wall << " frame " << a[i].frame;
  for (const char* wall : {"front", "left", "right", "floor"}) {
    const std::string image = test::readBytes(dir / "threads" / (std::string(wall) + ".png"));
    EXPECT_FALSE(image.empty()) << wall;
    EXPECT_EQ(image, test::readBytes(dir / "one" / (std::string(wall) + ".png")))
        << wall << ": the images differ";
  }
}

// The shadow map is built once per GPU from the particles (render.shadows):
// walls on their own threads, walls drawing one shared simulation, and a
// wall alone in its process (as an MPI rank runs it) show the same shadows.
TEST(Identity, ShadowsAreTheSameOnEveryWallHoweverTheWallsAreRun) {
  const auto dir = test::scratchDir("shadows");
  const std::string shadows =
      " --replay tests/data/midrun.session --frames 90 --set render.shadows=true "
      "--set render.shadow_density=6 --set render.light_direction=0.6,0.2,0.77 --screenshot ";
  const auto own =
      runSandstorm("--config tests/data/identity.toml" + shadows + (dir / "own").string());
  const auto shared = runSandstorm("--config tests/data/identity-shared.toml" + shadows +
                                   (dir / "shared").string());
  const auto alone = runSandstorm("--config tests/data/identity.toml --walls floor" + shadows +
                                  (dir / "alone").string());
  const auto unshaded = runSandstorm(
      "--config tests/data/identity.toml --replay tests/data/midrun.session "
      "--frames 90 --set render.light_direction=0.6,0.2,0.77 --screenshot " +
      (dir / "unshaded").string());
  for (const auto* r : {&own, &shared, &alone, &unshaded})
    ASSERT_EQ(r->exitCode, 0) << r->output;
  int shaded = 0;  // walls where the shadows show (32 pixels wide: not every wall's)
  for (const char* wall : {"front", "left", "right", "floor"}) {
    const std::string name = std::string(wall) + ".png";
    const std::string image = test::readBytes(dir / "own" / name);
    EXPECT_FALSE(image.empty()) << wall;
    EXPECT_TRUE(image == test::readBytes(dir / "shared" / name)) << wall << ": the images differ";
    shaded += image != test::readBytes(dir / "unshaded" / name);
  }
  EXPECT_GE(shaded, 2);
  EXPECT_TRUE(test::readBytes(dir / "own" / "floor.png") ==
              test::readBytes(dir / "alone" / "floor.png"));
}

// Every wall's hashes equal, frame by frame (the floor wall's, returned).
std::map<std::uint32_t, std::string> sameOnEveryWall(const std::filesystem::path& log,
                                                     std::size_t frames) {
  const std::vector<HashLine> lines = readHashes(log);
  EXPECT_EQ(lines.size(), 4u * frames);
  std::map<std::uint32_t, std::set<std::string>> perFrame;
  std::map<std::uint32_t, std::string> floor;
  for (const HashLine& h : lines) {
    perFrame[h.frame].insert(h.hash);
    if (h.wall == "floor") floor[h.frame] = h.hash;
  }
  for (const auto& [frame, hashes] : perFrame)
    EXPECT_EQ(hashes.size(), 1u) << "walls differ at frame " << frame;
  return floor;
}

TEST(Identity, AnObstacleMovingMidRunKeepsEveryWallIdentical) {
  const auto dir = test::scratchDir("obstacles");
  // Live: the sphere follows its path, a new place every frame; four walls on
  // threads, and one simulation shared by all four, hold the same particles.
  const std::string live = " --frames 150 --hash-log ";
  const auto threads =
      runSandstorm("--config tests/data/identity-obstacles.toml" + live +
                   (dir / "threads.txt").string() + " --record " + (dir / "live.session").string());
  const auto shared = runSandstorm("--config tests/data/identity-obstacles-shared.toml" + live +
                                   (dir / "shared.txt").string());
  const auto without =
      runSandstorm("--config tests/data/identity.toml" + live + (dir / "without.txt").string());
  for (const auto* r : {&threads, &shared, &without})
    ASSERT_EQ(r->exitCode, 0) << r->output;
  auto floor = sameOnEveryWall(dir / "threads.txt", 150);
  EXPECT_EQ(sameOnEveryWall(dir / "shared.txt", 150), floor);
  EXPECT_NE(sameOnEveryWall(dir / "without.txt", 150).at(149), floor[149]);  // the obstacles acted
  // The path's moves were recorded as changes, one a frame.
  int moves = 0;
  for (const std::string& line : readLines(dir / "live.session"))
    moves += line.find(" set obstacle.0.position ") != std::string::npos;
  EXPECT_GE(moves, 149);
  // By hand: the box at frame 60, the sphere at 100 (a replayed session); and
  // one wall alone in its own process holds the same particles as all four.
  const std::string moved =
      " --frames 150 --replay tests/data/obstacles-midrun.session --hash-log ";
  const auto hand = runSandstorm("--config tests/data/identity-obstacles.toml" + moved +
                                 (dir / "hand.txt").string());
  const auto alone = runSandstorm("--config tests/data/identity-obstacles.toml --walls floor" +
                                  moved + (dir / "alone.txt").string());
  for (const auto* r : {&hand, &alone})
    ASSERT_EQ(r->exitCode, 0) << r->output;
  auto handFloor = sameOnEveryWall(dir / "hand.txt", 150);
  for (const HashLine& h : readHashes(dir / "alone.txt"))
    EXPECT_EQ(h.hash, handFloor[h.frame]) << "frame " << h.frame;
  EXPECT_NE(handFloor[149], floor[149]);
}

// The field editor used mid-run (a vortex placed, moved and removed, a sink
// added): the composed field reaches every wall at the same frame, so four
// walls on threads and a wall alone in its process hold the same particles.
TEST(Identity, TheFieldEditorsPrimitivesReachEveryWallAtTheSameFrame) {
  const auto dir = test::scratchDir("field-editor-identity");
  const std::string run =
      " --frames 90 --replay tests/data/field-editor-midrun.session --hash-log ";
  const auto threads =
      runSandstorm("--config tests/data/identity.toml" + run + (dir / "threads.txt").string());
  const auto alone = runSandstorm("--config tests/data/identity.toml --walls floor" + run +
                                  (dir / "alone.txt").string());
  const auto without = runSandstorm("--config tests/data/identity.toml --frames 90 --hash-log " +
                                    (dir / "without.txt").string());
  for (const auto* r : {&threads, &alone, &without})
    ASSERT_EQ(r->exitCode, 0) << r->output;
  auto floor = sameOnEveryWall(dir / "threads.txt", 90);
  for (const HashLine& h : readHashes(dir / "alone.txt"))
    EXPECT_EQ(h.hash, floor[h.frame]) << "frame " << h.frame;
  const auto plain = sameOnEveryWall(dir / "without.txt", 90);
  EXPECT_EQ(plain.at(20), floor[20]);  // the vortex takes effect from frame 21's field
  EXPECT_NE(plain.at(89), floor[89]);
}

// The tornado as an OpenVDB grid kept sparse (field.storage = "sparse": its
// NanoVDB words on every GPU): the same particles on four walls on their
// threads and on one wall alone in its process, every frame.
TEST(Identity, ASparseGridMovesTheSameParticlesOnEveryWall) {
  const auto dir = test::scratchDir("sparse-identity");
  VortexParams vp;
  vp.range = 5.0f;
  vp.height = 9.0f;
  saveField(dir / "tornado.vdb", bake(VortexField(vp), Box{{-6, -6, 0}, {6, 6, 10}}, {49, 49, 41}),
            "velocity");
  {
    std::ofstream config(dir / "sparse.toml");
    config << "include = \"" << SANDSTORM_SOURCE_DIR << "/tests/data/identity.toml\"\n"
           << "[field]\nsource = \"tornado.vdb\"\nname = \"velocity\"\nstorage = \"sparse\"\n";
  }
  const std::string run = "--config " + (dir / "sparse.toml").string() + " --frames 90 --hash-log ";
  const auto threads = runSandstorm(run + (dir / "threads.txt").string());
  const auto alone = runSandstorm(run + (dir / "alone.txt").string() + " --walls floor");
  for (const auto* r : {&threads, &alone})
    ASSERT_EQ(r->exitCode, 0) << r->output;
  EXPECT_NE(threads.output.find("sparse: "), std::string::npos) << threads.output;
  auto floor = sameOnEveryWall(dir / "threads.txt", 90);
  for (const HashLine& h : readHashes(dir / "alone.txt"))
    EXPECT_EQ(h.hash, floor[h.frame]) << "frame " << h.frame;
  const std::vector<HashLine> lines = readHashes(dir / "threads.txt");
  ASSERT_FALSE(lines.empty());
  EXPECT_GT(lines.back().count, 3000u);
}

// Molecules beside the particles, changed mid-run (a new shape, the push
// tool, repulsion): the same on four walls each simulating its own, on four
// walls sharing one simulation, and on one wall alone in its process.
TEST(Identity, MoleculesAreTheSameOnEveryWallHoweverTheWallsAreRun) {
  const auto dir = test::scratchDir("molecules");
  const std::string run = " --frames 130 --replay tests/data/molecules-midrun.session --hash-log ";
  const auto threads = runSandstorm("--config tests/data/identity-molecules.toml" + run +
                                    (dir / "threads.txt").string());
  const auto shared = runSandstorm("--config tests/data/identity-molecules-shared.toml" + run +
                                   (dir / "shared.txt").string());
  const auto alone = runSandstorm("--config tests/data/identity-molecules.toml --walls floor" +
                                  run + (dir / "alone.txt").string());
  const auto without = runSandstorm("--config tests/data/identity.toml --frames 130 --hash-log " +
                                    (dir / "without.txt").string());
  for (const auto* r : {&threads, &shared, &alone, &without})
    ASSERT_EQ(r->exitCode, 0) << r->output;
  auto floor = sameOnEveryWall(dir / "threads.txt", 130);
  EXPECT_EQ(sameOnEveryWall(dir / "shared.txt", 130), floor);
  for (const HashLine& h : readHashes(dir / "alone.txt"))
    EXPECT_EQ(h.hash, floor[h.frame]) << "frame " << h.frame;
  // The molecules are in the hashes: without them the particles' hash differs.
  const auto plain = sameOnEveryWall(dir / "without.txt", 130);
  EXPECT_NE(plain.at(129), floor[129]);
}

// The live flow solved on each wall's GPU (solver.device = gpu): four walls
// on threads, four sharing one simulation and a wall alone in its process hold
// the same particles every frame, and the solver changed them. Solved in the
// main context (solver.device = cpu), its grids travel to the walls and they
// agree too.
TEST(Identity, TheLiveSolversFlowIsTheSameOnEveryWall) {
  const auto dir = test::scratchDir("solver");
  // Ten solver steps of four pressure iterations: every stage of the GPU
  // solver, at a fifteenth of the default's cost on llvmpipe.
  const std::string run =
      " --frames 40 --set solver.enabled=true --set solver.device=gpu --set solver.every=4"
      " --set solver.iterations=4 --hash-log ";
  const auto threads =
      runSandstorm("--config tests/data/identity.toml" + run + (dir / "threads.txt").string());
  const auto shared = runSandstorm("--config tests/data/identity-shared.toml" + run +
                                   (dir / "shared.txt").string());
  const auto alone = runSandstorm("--config tests/data/identity.toml --walls floor" + run +
                                  (dir / "alone.txt").string());
  const auto without = runSandstorm("--config tests/data/identity.toml --frames 40 --hash-log " +
                                    (dir / "without.txt").string());
  const auto cpu = runSandstorm("--config tests/data/identity.toml --set solver.device=cpu" +
                                std::string(" --frames 40 --set solver.enabled=true --hash-log ") +
                                (dir / "cpu.txt").string());
  for (const auto* r : {&threads, &shared, &alone, &without, &cpu})
    ASSERT_EQ(r->exitCode, 0) << r->output;
  auto floor = sameOnEveryWall(dir / "threads.txt", 40);
  EXPECT_EQ(sameOnEveryWall(dir / "shared.txt", 40), floor);
  for (const HashLine& h : readHashes(dir / "alone.txt"))
    EXPECT_EQ(h.hash, floor[h.frame]) << "frame " << h.frame;
  EXPECT_NE(sameOnEveryWall(dir / "without.txt", 40).at(39), floor[39]);
  EXPECT_NE(sameOnEveryWall(dir / "cpu.txt", 40).at(39),
            sameOnEveryWall(dir / "without.txt", 40).at(39));
}

TEST(Identity, ARecordedSessionReplaysToTheSameParticles) {
  const auto dir = test::scratchDir("replay");
  const auto first =
      runSandstorm(kRun + "--frames 180 --walls front --record " + (dir / "rec.session").string() +
                   " --hash-log " + (dir / "first.txt").string());
  ASSERT_EQ(first.exitCode, 0) << first.output;
  const std::vector<std::string> recorded = readLines(dir / "rec.session");
  // A header, the navigation at frame 0 and the four changes that took effect before frame 180.
  ASSERT_EQ(recorded.size(), 6u);
  EXPECT_EQ(recorded[1], "0 navigate -1,2.6,0,0,0.35");
  const auto again =
      runSandstorm("--config tests/data/identity.toml --frames 180 --walls front --replay " +
                   (dir / "rec.session").string() + " --hash-log " + (dir / "again.txt").string());
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_EQ(readLines(dir / "first.txt"), readLines(dir / "again.txt"));
  // Without the changes the run differs: the comparison can fail.
  const auto plain =
      runSandstorm("--config tests/data/identity.toml --frames 180 --walls front --hash-log " +
                   (dir / "plain.txt").string());
  EXPECT_NE(readLines(dir / "first.txt"), readLines(dir / "plain.txt"));
}

}  // namespace
}  // namespace sandstorm
