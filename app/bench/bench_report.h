// sandstorm-bench's results: one row per measured stage, printed as a table
// and written as JSON.
#pragma once

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace sandstorm::bench {

struct Row {
  std::string section;  // ceilings | update | render | walls
  std::string stage;    // copy, bare-tf, bare-points, update, scene, particles, post, frame
  std::string backend, field, renderer, sim;
  std::size_t particles = 0;
  int walls = 0;
  int trails = 0;        // walls: render.trail_length
  bool shadows = false;  // walls: render.shadows
  int obstacles = 0;     // update: how many obstacles (SceneChoice::obstacles)
  int molecules = 0;     // update: molecules of this many members (0: particles)
  int width = 0, height = 0;
  double ms = 0;             // GPU milliseconds per frame (median)
  double particlesPerS = 0;  // 0: not applicable
  double bytesPerS = 0;      // 0: not applicable
  std::string ceiling;       // what `ratio` compares with
  double ratio = 0;          // this stage's rate over the ceiling's (0: none)
  double wallMs = 0;         // walls: wall-clock milliseconds per frame (CPU included)
  std::string note;
};

struct Report {
  std::string device;
  std::string command;
  double copyBytesPerS = 0;        // glCopyNamedBufferSubData
  double shaderCopyBytesPerS = 0;  // a compute shader's copy
  // The bandwidth ceiling stages are compared with: the larger of the two.
  double bandwidth() const { return std::max(copyBytesPerS, shaderCopyBytesPerS); }
  std::string bandwidthName() const {
    return shaderCopyBytesPerS > copyBytesPerS ? "copy-shader" : "copy";
  }
  std::vector<Row> rows;
};

void printTable(const Report& report);
void writeJson(const Report& report, const std::filesystem::path& path);

}  // namespace sandstorm::bench
