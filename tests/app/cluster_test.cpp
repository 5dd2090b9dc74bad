// Cluster mode on MPI, proven on this machine: three ranks over loopback TCP,
// headless EGL. Every wall on every rank holds the single process's particles
// every frame (mid-run changes and a time-varying field included), writes the
// same PNGs, and faults (a rank that dies, hangs, has no OpenGL, or is
// missing) stop every rank with a clear message within the configured bound.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "tests/app/run_process.h"
#include "tests/app/tracked_run.h"

namespace sandstorm {
namespace {

using test::readLines;
using test::runSandstorm;

struct MpiRun {
  int exitCode = -1;
  std::string output;
  double seconds = 0.0;
};

std::string mpirunCommand(const std::string& apps) {
  return std::string("cd '") + SANDSTORM_SOURCE_DIR +
         "' && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 '" + SANDSTORM_MPIRUN +
         "' --oversubscribe --mca btl self,tcp --mca btl_tcp_if_include lo"
         " --mca oob_tcp_if_include lo " +
         apps + " 2>&1";
}

// `apps`: mpirun's "-np N program args [: -np M program args]". As root,
// mpirun needs consent; --oversubscribe: three ranks on two cores. TCP on the
// loopback interface stands in for a cluster's network.
MpiRun mpirun(const std::string& apps) {
  const std::string cmd = mpirunCommand(apps);
  const auto start = std::chrono::steady_clock::now();
  const test::ProcessResult run = test::runCommand(cmd);
  MpiRun r;
  r.output = run.output;
  r.exitCode = run.exitCode;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

// N ranks of sandstorm, every one with the same arguments.
MpiRun ranks(int n, const std::string& args) {
  return mpirun("-np " + std::to_string(n) + " '" + SANDSTORM_BINARY + "' " + args);
}

bool has(const std::string& output, const std::string& part) {
  return output.find(part) != std::string::npos;
}

std::string readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

int count(const std::string& output, const std::string& part) {
  int n = 0;
  for (std::size_t at = output.find(part); at != std::string::npos; at = output.find(part, at + 1))
    ++n;
  return n;
}

// "frame wall count bufferhash statehash" lines by (frame, wall).
std::map<std::pair<int, std::string>, std::string> hashLines(const std::filesystem::path& path) {
  std::map<std::pair<int, std::string>, std::string> out;
  for (const std::string& line : readLines(path)) {
    std::istringstream in(line);
    int frame;
    std::string wall;
    in >> frame >> wall;
    out[{frame, wall}] = line;
  }
  return out;
}

// Runs `config` in one process and on three ranks; every rank's walls must
// match the single process's line for line, every frame.
// Returns mpirun's output.
std::string expectSameHashes(const std::string& config, const std::string& extra, int frames,
                             const std::string& name) {
  const auto dir = test::scratchDir(name);
  const std::string args =
      "--config " + config + " --frames " + std::to_string(frames) + " " + extra;
  const auto one = runSandstorm(args + " --hash-log " + (dir / "one.txt").string());
  EXPECT_EQ(one.exitCode, 0) << one.output;
  const auto reference = hashLines(dir / "one.txt");
  EXPECT_EQ(reference.size(), 4u * std::size_t(frames));

  const MpiRun cluster =
      ranks(3, args + " --cluster-stats --hash-log " + (dir / "rank{rank}.txt").string());
  EXPECT_EQ(cluster.exitCode, 0) << cluster.output;
  const std::map<int, std::set<std::string>> expectedWalls = {
      {0, {"front"}}, {1, {"left", "floor"}}, {2, {"right"}}};
  std::size_t compared = 0;
  for (const auto& [rank, walls] : expectedWalls) {
    const auto lines = hashLines(dir / ("rank" + std::to_string(rank) + ".txt"));
    EXPECT_EQ(lines.size(), walls.size() * std::size_t(frames)) << "rank " << rank;
    for (const auto& [key, line] : lines) {
      EXPECT_TRUE(walls.count(key.second)) << "rank " << rank << " drew wall " << key.second;
      const auto it = reference.find(key);
      if (it == reference.end()) {
        ADD_FAILURE() << "not in the single process's log: " << line;
        continue;
      }
      EXPECT_EQ(line, it->second) << "rank " << rank << " differs from one process at frame "
                                  << key.first;
      ++compared;
    }
  }
  EXPECT_EQ(compared, reference.size());
  // Every rank reports its costs; a packet is about a hundred bytes.
  for (int rank = 0; rank < 3; ++rank)
    EXPECT_TRUE(has(cluster.output, "cluster stats, rank " + std::to_string(rank) + " of 3"))
        << cluster.output;
  return cluster.output;
}

TEST(Cluster, ThreeRanksHoldTheSameParticlesAsOneProcessEveryFrame) {
  const std::string output =
      expectSameHashes("tests/data/identity-cluster.toml", "--replay tests/data/midrun.session",
                       200, "cluster-hash");
  EXPECT_EQ(count(output, "field grids: 1 ("), 3)
      << output;  // the field crossed once, to every rank
}

// The live flow solved on the main context's CPU (solver.device = cpu) runs
// on rank 0: its grids cross to the other ranks as they change, and every rank
// holds one process's particles.
TEST(Cluster, TheCpuSolversFlowReachesEveryRankAtTheSameFrame) {
  const std::string output =
      expectSameHashes("tests/data/identity-cluster.toml",
                       "--set solver.enabled=true --set solver.device=cpu", 40, "cluster-solver");
  EXPECT_EQ(count(output, "field grids: 40 ("), 3) << output;  // a new grid every frame
}

// Solved on the GPUs (solver.device = gpu): every rank steps the
// same flow from the same packets, so only the field's first grid crosses and
// every rank still holds one process's particles.
TEST(Cluster, EveryRanksGpuSolvesTheSameFlow) {
  const std::string output = expectSameHashes("tests/data/identity-cluster-gpu-solver.toml",
                                              "--set solver.enabled=true --set solver.device=gpu "
                                              "--set solver.every=4 --set solver.iterations=4",
                                              40, "cluster-gpu-solver");
  EXPECT_EQ(count(output, "field grids: 1 ("), 3) << output;
}

TEST(Cluster, ATimeVaryingFieldSendsEachGridOnce) {
  // 120 frames are 2 s of the four-frame series (0.5 s apart): every grid is
  // needed once, and none travels twice.
  const std::string output =
      expectSameHashes("tests/data/series-cluster.toml", "", 120, "cluster-series");
  EXPECT_EQ(count(output, "field grids: 4 ("), 3) << output;
  EXPECT_EQ(count(output, " 512 B/frame broadcast"), 3)
      << output;  // one slot per frame, grids apart
}

// cluster.steps = "read" (the default): every rank reads the series' steps
// from the (here: the same) disk itself, checked by file against rank 0's,
// and no grid crosses.
TEST(Cluster, EveryRankReadsTheSeriesStepsItselfAndNoGridCrosses) {
  const std::string output =
      expectSameHashes("tests/data/series-read-cluster.toml", "", 120, "cluster-series-read");
  EXPECT_EQ(count(output, "field grids: 0 ("), 3) << output;
  EXPECT_EQ(count(output, "series steps read here: 4 ("), 2) << output;  // ranks 1 and 2
  EXPECT_TRUE(has(output, "the series' steps are read from disk by rank(s) 0, 1, 2")) << output;
}

// A rank that cannot see the series' files (here it is told to behave so)
// gets its steps from rank 0 over MPI, says so once, and draws the same.
TEST(Cluster, ARankThatCannotSeeTheSeriesGetsItsStepsOverMpi) {
  const std::string output = expectSameHashes(
      "tests/data/series-read-cluster.toml", "--debug-blind-to-steps", 120, "cluster-series-blind");
  EXPECT_EQ(count(output, "cannot read the series' steps itself"), 1) << output;
  EXPECT_TRUE(has(output, "rank 0 sends them over MPI to rank(s) 2")) << output;
  // Rank 1 reads all four steps; rank 2 receives them.
  for (const auto& [rank, grids] :
       {std::pair{1, "field grids: 0 ("}, std::pair{2, "field grids: 4 ("}}) {
    const std::string line = "cluster stats, rank " + std::to_string(rank) + " of 3";
    const std::size_t at = output.find(line);
    ASSERT_NE(at, std::string::npos) << output;
    const std::string stats = output.substr(at, output.find('\n', at) - at);
    EXPECT_TRUE(has(stats, grids)) << stats;
  }
}

// A watched folder (a running simulation's steps, here all written before
// the start) on three ranks: a series that grows on rank 0. Each rank opens
// its first step itself, each step that joins on rank 0 is announced to the
// others by its file, and every rank's reader reads the steps its playback
// needs, checked by file against rank 0's, as for a series. Played from its
// start, 90 frames (1.5 s) use all four steps (0.5 s apart). Every wall of
// every rank holds the same particles at every frame. `extra`: more
// arguments; returns mpirun's output.
std::string runWatched(const std::string& name, const std::string& extra) {
  const auto dir = test::scratchDir(name);
  std::filesystem::create_directories(dir / "steps");
  for (int k = 0; k < 4; ++k) {
    const std::string step = "step_00" + std::to_string(k) + ".vti";
    std::filesystem::copy_file(std::filesystem::path(SANDSTORM_SOURCE_DIR) / "data/series" / step,
                               dir / "steps" / step);
  }
  std::ofstream(dir / "watched.toml")
      << "include = \"" << SANDSTORM_SOURCE_DIR << "/tests/data/identity-cluster.toml\"\n"
      << "[field]\nsource = \"steps\"\nstep_interval = 0.5\n"
      << "[field_playback]\nloop = false\n";
  const MpiRun run = ranks(3, "--config " + (dir / "watched.toml").string() +
                                  " --frames 90 --cluster-stats --hash-log " +
                                  (dir / "rank{rank}.txt").string() + " " + extra);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(count(run.output, ") joins the field at frame "), 3) << run.output;
  // Frame by frame, every wall's count and particle hash.
  std::map<int, std::set<std::string>> particles;
  for (int rank = 0; rank < 3; ++rank)
    for (const auto& [key, line] : hashLines(dir / ("rank" + std::to_string(rank) + ".txt"))) {
      std::istringstream in(line);
      std::string frame, wall, live, hash;
      in >> frame >> wall >> live >> hash;
      particles[key.first].insert(live + " " + hash);
    }
  EXPECT_EQ(particles.size(), 90u);
  for (const auto& [frame, seen] : particles)
    EXPECT_EQ(seen.size(), 1u) << "the walls differ at frame " << frame;
  return run.output;
}

std::string statsOf(const std::string& output, int rank) {
  const std::string line = "cluster stats, rank " + std::to_string(rank) + " of 3";
  const std::size_t at = output.find(line);
  if (at == std::string::npos) return "";
  return output.substr(at, output.find('\n', at) - at);
}

TEST(Cluster, EveryRankReadsAWatchedFoldersStepsItself) {
  const std::string output = runWatched("cluster-watched", "");
  EXPECT_TRUE(has(output, "the series' steps are read from disk by rank(s) 0, 1, 2")) << output;
  for (int rank : {1, 2}) {
    const std::string stats = statsOf(output, rank);
    EXPECT_TRUE(has(stats, "field grids: 0 (")) << stats;
    EXPECT_TRUE(has(stats, "series steps read here: 4 (")) << stats;
  }
}

// A rank that cannot see the watched folder gets its steps from rank 0 over
// MPI, says so once, and draws the same; the others still read them.
TEST(Cluster, ARankThatCannotSeeAWatchedFolderGetsItsStepsOverMpi) {
  const std::string output = runWatched("cluster-watched-blind", "--debug-blind-to-steps");
  EXPECT_EQ(count(output, "cannot read the series' steps itself"), 1) << output;
  EXPECT_TRUE(has(output, "rank 0 sends them over MPI to rank(s) 2")) << output;
  EXPECT_TRUE(has(statsOf(output, 2), "field grids: 4 (")) << statsOf(output, 2);
  EXPECT_TRUE(has(statsOf(output, 1), "series steps read here: 4 (")) << statsOf(output, 1);
}

TEST(Cluster, AHalfPrecisionSeriesTravelsAsHalvesAndDrawsTheSameEverywhere) {
  const std::string output =
      expectSameHashes("tests/data/series-half-cluster.toml", "", 60, "cluster-series-half");
  // Three grids of 20x20x12 points reach each rank (1 s of the series), at
  // 6 bytes a vector and 84 of header and flags: 86652 bytes (as floats: 173052).
  EXPECT_EQ(count(output, "field grids: 3 (86652 B"), 3) << output;
}

TEST(Cluster, HeadlessPngsEqualTheSingleProcessOnes) {
  const auto dir = test::scratchDir("cluster-png");
  const auto one =
      runSandstorm("--config tests/data/cluster-png.toml --screenshot " + (dir / "one").string());
  ASSERT_EQ(one.exitCode, 0) << one.output;
  const MpiRun cluster = ranks(
      3, "--config tests/data/cluster-png-ranks.toml --screenshot " + (dir / "three").string());
  ASSERT_EQ(cluster.exitCode, 0) << cluster.output;
  EXPECT_TRUE(has(cluster.output, "every rank read the same field")) << cluster.output;
  for (const std::string wall : {"front", "left", "right", "floor"}) {
    const std::string a = readBytes(dir / "one" / (wall + ".png"));
    const std::string b = readBytes(dir / "three" / (wall + ".png"));
    ASSERT_FALSE(a.empty()) << wall;
    EXPECT_TRUE(a == b) << wall << ".png differs between one process and three ranks";
  }
}

// The legend on a wall rank 1 drives, turned on and changed mid-run by a
// replayed session on rank 0: rank 1 builds it from the packets it receives,
// and the image equals one process's, where the main context builds it.
TEST(Cluster, ALegendOnAnotherRanksWallEqualsTheSingleProcessOne) {
  const auto dir = test::scratchDir("cluster-legend");
  const std::string replay = " --replay tests/data/legend-midrun.session";
  const auto one = runSandstorm("--config tests/data/cluster-legend.toml --screenshot " +
                                (dir / "one").string() + replay);
  ASSERT_EQ(one.exitCode, 0) << one.output;
  const auto plain = runSandstorm("--config tests/data/cluster-legend.toml --screenshot " +
                                  (dir / "plain").string());
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  const MpiRun cluster = ranks(3, "--config tests/data/cluster-legend-ranks.toml --screenshot " +
                                      (dir / "three").string() + replay);
  ASSERT_EQ(cluster.exitCode, 0) << cluster.output;
  EXPECT_NE(readBytes(dir / "one" / "left.png"), readBytes(dir / "plain" / "left.png"))
      << "no legend drawn on 'left'";
  for (const std::string wall : {"front", "left", "right", "floor"}) {
    const std::string a = readBytes(dir / "one" / (wall + ".png"));
    ASSERT_FALSE(a.empty()) << wall;
    EXPECT_TRUE(a == readBytes(dir / "three" / (wall + ".png")))
        << wall << ".png differs between one process and three ranks";
  }
}

// A tracked CAVE on three ranks: only rank 0 listens to the tracker; every
// rank's walls draw what one process replaying rank 0's recorded session
// draws, image for image, with the same particles every frame.
TEST(Cluster, TrackedRanksDrawWhatOneProcessReplaysWithoutTheTracker) {
  const auto dir = test::scratchDir("cluster-tracked");
  const int port = test::freeUdpPort();
  const auto config = test::trackedConfig(dir, "tests/data/tracked-cluster.toml", port);
  const std::string args = "--config " + config.string() + " --frames 90 --screenshot-every 30";
  const test::TrackedResult cluster = test::runTrackedCommand(
      mpirunCommand("-np 3 '" + std::string(SANDSTORM_BINARY) + "' " + args + " --screenshot " +
                    (dir / "three").string() + " --record " + (dir / "session.log").string() +
                    " --hash-log " + (dir / "rank{rank}.txt").string()),
      "--port " + std::to_string(port) + " --rate 250 --duration 60", dir);
  ASSERT_EQ(cluster.exitCode, 0) << cluster.output;
  EXPECT_EQ(count(cluster.output, "listening for DTrack"), 1) << cluster.output;  // rank 0 only
  const auto one =
      runSandstorm(args + " --screenshot " + (dir / "one").string() + " --replay " +
                   (dir / "session.log").string() + " --hash-log " + (dir / "one.txt").string());
  ASSERT_EQ(one.exitCode, 0) << one.output;
  int tracked = 0;
  for (const std::string& line : readLines(dir / "session.log"))
    tracked += line.find(" track ") != std::string::npos ? 1 : 0;
  EXPECT_GT(tracked, 10) << "the session recorded no tracking";
  for (const std::string wall : {"front", "left", "right", "floor"})
    for (const std::string frame : {"_0", "_30", "_60", ""}) {
      const std::string a = readBytes(dir / "one" / (wall + frame + ".png"));
      ASSERT_FALSE(a.empty()) << wall << frame;
      EXPECT_TRUE(a == readBytes(dir / "three" / (wall + frame + ".png")))
          << wall << frame << ".png differs between three ranks and one process";
    }
  const auto reference = hashLines(dir / "one.txt");
  std::size_t compared = 0;
  for (int rank = 0; rank < 3; ++rank)
    for (const auto& [key, line] : hashLines(dir / ("rank" + std::to_string(rank) + ".txt"))) {
      EXPECT_EQ(line, reference.at(key)) << "rank " << rank;
      ++compared;
    }
  EXPECT_EQ(compared, reference.size());
}

TEST(Cluster, AWallOnAMissingRankFailsBeforeAnythingStarts) {
  const MpiRun r = ranks(2, "--config tests/data/identity-cluster.toml");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_TRUE(
      has(r.output,
          "identity-cluster.toml:8: cluster.ranks.right (wall 'right'): rank 2 does not exist; "
          "mpirun started 2 ranks (0..1)"))
      << r.output;
  EXPECT_FALSE(has(r.output, "EGL")) << "no context should have been made:\n" << r.output;
}

TEST(Cluster, ARankWithoutOpenGLStopsEveryRankBeforeTheFirstFrame) {
  // Rank 2 finds no EGL driver (an empty vendor list), as on a node without one.
  const std::string args = " --config tests/data/identity-cluster.toml --hash-log /dev/null";
  const MpiRun r = mpirun(std::string("-np 2 '") + SANDSTORM_BINARY + "'" + args +
                          " : -np 1 env __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json '" +
                          SANDSTORM_BINARY + "'" + args);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_TRUE(has(r.output, "rank 2 (")) << r.output;
  EXPECT_TRUE(has(r.output, "cannot start: tests/data/identity-cluster.toml:")) << r.output;
  EXPECT_TRUE(has(r.output, "wall 'right' on GPU 0: EglContext: no usable EGL display"))
      << r.output;
  EXPECT_TRUE(has(r.output, "stopping every rank before the first frame")) << r.output;
  EXPECT_FALSE(has(r.output, "stats:")) << r.output;
  EXPECT_LT(r.seconds, 20.0);
}

TEST(Cluster, ADeadRankStopsEveryRankWithAClearError) {
  const MpiRun r = ranks(3, "--config tests/data/identity-cluster.toml --debug-die-at-frame 30");
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_TRUE(has(r.output, "rank 2: --debug-die-at-frame 30: dying now")) << r.output;
  // mpirun names the rank that died and stops the others.
  EXPECT_TRUE(has(r.output, "process rank 2")) << r.output;
  EXPECT_FALSE(has(r.output, "stats:")) << "no rank should have finished:\n" << r.output;
  EXPECT_LT(r.seconds, 3.0 /* cluster.timeout_s */ + 15.0) << r.output;
}

TEST(Cluster, ADamagedPacketStopsEveryRankWithAClearMessage) {
  // Rank 0 flips a byte of frame 30's packet after checksumming it.
  const MpiRun r =
      ranks(3, "--config tests/data/identity-cluster.toml --debug-corrupt-at-frame 30");
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_TRUE(has(r.output, "the packet of frame 30 from rank 0 arrived damaged")) << r.output;
  EXPECT_TRUE(has(r.output, "stopping every rank")) << r.output;
  EXPECT_FALSE(has(r.output, "stats:")) << "no rank should have finished:\n" << r.output;
}

TEST(Cluster, AHungRankStopsEveryRankWithinTheTimeout) {
  const MpiRun r =
      ranks(3, "--config tests/data/identity-cluster.toml --debug-hang-at-frame 30 --debug-rank 1");
  EXPECT_EQ(r.exitCode, 3) << r.output;  // MPI_Abort's status
  EXPECT_TRUE(
      has(r.output,
          "[sandstorm rank 0 error] no answer within 3 s while waiting for every rank to draw "
          "frame 30 (the swap barrier): a rank died or hangs"))
      << r.output;
  EXPECT_FALSE(has(r.output, "stats:")) << r.output;
  EXPECT_LT(r.seconds, 3.0 + 15.0) << r.output;
}

TEST(Cluster, RanksWithAnotherConfigurationAreRefused) {
  const MpiRun r =
      mpirun(std::string("-np 2 '") + SANDSTORM_BINARY +
             "' --config tests/data/identity-cluster.toml : -np 1 '" + SANDSTORM_BINARY +
             "' --config tests/data/identity-cluster.toml --set render.size=0.2");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_TRUE(has(r.output, "rank 2 (")) << r.output;
  EXPECT_TRUE(has(r.output, "configuration differs from rank 0's")) << r.output;
  EXPECT_TRUE(has(r.output, "render.size")) << r.output;
}

TEST(Cluster, TheBenchReportsOneSlotPerFrame) {
  const MpiRun r =
      ranks(2, "--config tests/data/cluster-bench.toml --cluster-bench 300 --cluster-stats");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(has(r.output, "cluster bench: 300 frames")) << r.output;
  EXPECT_EQ(count(r.output, "300 packets"), 2) << r.output;
  EXPECT_EQ(count(r.output, " 512 B/frame broadcast"), 2) << r.output;
}

}  // namespace
}  // namespace sandstorm
