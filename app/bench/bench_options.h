// sandstorm-bench's command line: what to sweep and how long to time it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sandstorm::bench {

struct BenchOptions {
  bool quick = false;
  std::string json = "sandstorm-bench.json";
  int warmup = 5;   // untimed frames after the particles are in place
  int frames = 20;  // timed frames; each stage's median is reported
  glm::ivec2 size{1920, 1080};
  float particleSize = 0.045f;  // m: about 3 pixels across at the views' distance
  std::vector<std::string> sections{"verify", "ceilings", "update", "render", "walls", "sort"};
  std::size_t verifyParticles = 1000000;
  std::vector<std::size_t> particles{10000, 100000, 1000000, 10000000, 30000000, 100000000};
  std::vector<std::string> backends{"tf-gs", "compute"};
  std::vector<std::string> fields{"texture", "equation"};
  std::vector<std::string> renderers{"billboards", "points", "splat", "splat-atomic"};
  std::size_t billboardLimit = 30000000;  // billboards beyond this many particles take too long
  std::vector<int> walls{1, 2, 4, 8};
  std::size_t wallParticles = 10000000;
  std::vector<std::string> wallSims{"per-wall", "shared"};
  std::vector<std::string> wallRenderers{"billboards", "splat"};
  std::vector<int> wallTrails{0};
  std::vector<int> wallShadows{0};      // render.shadows off (0), on (1)
  std::vector<int> updateMolecules{0};  // the update section's particles (0) or molecules of n
  std::vector<int> updateObstacles{0};  // obstacles in the update section: 0, 1 (a sphere) or 2
  std::vector<std::size_t> sortKeys{1000000, 10000000};  // the sort section's sizes
  std::vector<glm::ivec3> solverGrids{{128, 128, 64}};   // the solver section's grids (cells)
  int solverIterations = 40;                             // its pressure iterations a step
  std::string wallBackend = "compute";
  std::string integrator = "rk2";  // euler | rk2 | rk4 (tracer particles)
  double gpuWarmupSeconds = 5.0;   // the GPU kept busy before the first measurement
  // Untimed frames of each walls configuration last at least this long (and
  // --warmup frames): on an H100 a process's first configuration ran 2.7x
  // slower for its first half second or so, whatever the GPU did before.
  double wallWarmupSeconds = 1.0;
  int updateItems = 4;   // records an invocation of the compute update ([gpu])
  double memoryGiB = 0;  // 0: what the driver reports, else unlimited
};

// Parses argv; throws Error on a bad option. `--help` prints usage and exits 0.
BenchOptions parseBenchOptions(int argc, char** argv);

}  // namespace sandstorm::bench
