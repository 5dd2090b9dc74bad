#include "core/util/parallel_for.h"

#include <algorithm>

namespace sandstorm {
namespace {

void chunk(std::size_t count, unsigned parts, unsigned index, std::size_t& begin,
           std::size_t& end) {
  begin = count * index / parts;
  end = count * (index + 1) / parts;
}

thread_local unsigned chunkThreadLimit = 0;  // 0: none

}  // namespace

ChunkThreadLimit::ChunkThreadLimit(unsigned threads) : previous_(chunkThreadLimit) {
  chunkThreadLimit = std::max(threads, 1u);
}

ChunkThreadLimit::~ChunkThreadLimit() {
  chunkThreadLimit = previous_;
}

ParallelFor::ParallelFor(unsigned threads) {
  if (threads == 0) threads = std::clamp(std::thread::hardware_concurrency(), 1u, 16u);
  for (unsigned i = 1; i < threads; ++i)
    workers_.emplace_back([this, i] { work(i); });
}

ParallelFor::~ParallelFor() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  start_.notify_all();
  for (std::thread& t : workers_)
    t.join();
}

void ParallelFor::work(unsigned index) {
  std::uint64_t seen = 0;
  for (;;) {
    std::unique_lock lock(mutex_);
    start_.wait(lock, [&] { return stop_ || generation_ != seen; });
    if (stop_) return;
    seen = generation_;
    const auto* body = body_;
    const std::size_t count = count_;
    lock.unlock();
    std::size_t begin, end;
    chunk(count, threads(), index, begin, end);
    if (begin < end) (*body)(begin, end);
    lock.lock();
    if (--pending_ == 0) done_.notify_one();
  }
}

void ParallelFor::run(std::size_t count,
                      const std::function<void(std::size_t, std::size_t)>& body) {
  if (workers_.empty() || count < 2) {
    if (count > 0) body(0, count);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    body_ = &body;
    count_ = count;
    pending_ = unsigned(workers_.size());
    ++generation_;
  }
  start_.notify_all();
  std::size_t begin, end;
  chunk(count, threads(), 0, begin, end);
  if (begin < end) body(begin, end);
  std::unique_lock lock(mutex_);
  done_.wait(lock, [&] { return pending_ == 0; });
}

void forChunks(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body,
               std::size_t grain) {
  const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t limit = chunkThreadLimit == 0 ? 16 : chunkThreadLimit;
  const std::size_t threads = std::clamp<std::size_t>(
      std::min({cores, count / std::max<std::size_t>(grain, 1), limit}), 1, 16);
  std::vector<std::jthread> workers;
  for (std::size_t t = 1; t < threads; ++t)
    workers.emplace_back(body, count * t / threads, count * (t + 1) / threads);
  body(0, count / threads);
}

}  // namespace sandstorm
