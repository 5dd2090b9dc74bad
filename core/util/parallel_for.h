// ParallelFor: a fixed pool of worker threads that splits an index range into
// contiguous chunks, one per thread, and returns once every chunk is done.
// The split depends only on the range and the thread count, and each index
// is handled exactly once, so a body that writes disjoint data computes the
// same result whatever the threads' timing (FluidSolver relies on it). Made
// on one thread and used from it; the workers live as long as the pool.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace sandstorm {

// body(begin, end) over [0, count) in contiguous chunks on threads started for
// the call (up to the machine's cores, 16 at most, one per `grain` indices at
// least), this one included; returns once all are done. For one-off passes
// over a large grid from any thread, where a pool would sit idle between them.
void forChunks(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body,
               std::size_t grain = std::size_t{1} << 16);

// While one lives, forChunks called on its thread uses at most `threads`
// threads (this one included; at least 1). For a thread that is one of
// several doing such passes at once, each over its own data (a series'
// readers, a step each): it takes its share of the cores, so that the
// walls' threads and the uploads are not crowded out by readers that each
// start one thread per core. Nests; the previous limit returns with it.
class ChunkThreadLimit {
 public:
  explicit ChunkThreadLimit(unsigned threads);
  ~ChunkThreadLimit();
  ChunkThreadLimit(const ChunkThreadLimit&) = delete;
  ChunkThreadLimit& operator=(const ChunkThreadLimit&) = delete;

 private:
  unsigned previous_;
};

class ParallelFor {
 public:
  // `threads` 0: the machine's hardware threads (at most 16).
  explicit ParallelFor(unsigned threads = 0);
  ~ParallelFor();
  ParallelFor(const ParallelFor&) = delete;
  ParallelFor& operator=(const ParallelFor&) = delete;

  // Calls body(begin, end) over [0, count) in chunks, on every thread (this one too).
  void run(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body);
  unsigned threads() const { return unsigned(workers_.size()) + 1; }

 private:
  void work(unsigned index);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_, done_;
  const std::function<void(std::size_t, std::size_t)>* body_ = nullptr;
  std::size_t count_ = 0;
  std::uint64_t generation_ = 0;
  unsigned pending_ = 0;
  bool stop_ = false;
};

}  // namespace sandstorm
