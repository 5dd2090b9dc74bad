// HashLog (--hash-log): per frame and wall, "frame wall particles buffer-hash
// state-hash" (the buffer hash covers the particles' records and then the
// molecules' members), written sorted at the end. Walls on any thread, process or MPI
// rank that hold the same particles and state print the same lines.
#pragma once

#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

namespace sandstorm {

class WallRenderer;

class HashLog {
 public:
  void add(const WallRenderer& wall, std::uint32_t frame);  // thread-safe
  void write(const std::filesystem::path& path);

 private:
  std::mutex mutex_;
  std::vector<std::string> lines_;
};

}  // namespace sandstorm
