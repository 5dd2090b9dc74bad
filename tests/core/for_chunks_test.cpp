// forChunks: every index of the range exactly once, in contiguous chunks,
// whatever the count against the grain (none, fewer than a grain, many).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "core/util/parallel_for.h"

namespace sandstorm {
namespace {

TEST(ForChunks, VisitsEveryIndexOnce) {
  for (const std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{999},
                                  std::size_t{1} << 16, (std::size_t{1} << 20) + 7}) {
    std::vector<std::atomic<int>> seen(count);
    std::atomic<int> chunks{0};
    forChunks(count, [&](std::size_t begin, std::size_t end) {
      EXPECT_LE(begin, end);
      ++chunks;
      for (std::size_t i = begin; i < end; ++i)
        ++seen[i];
    });
    for (std::size_t i = 0; i < count; ++i)
      ASSERT_EQ(seen[i].load(), 1) << "index " << i << " of " << count;
    EXPECT_GE(chunks.load(), 1);
  }
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

// Chunks a large range splits into on this thread.
int chunksOf(std::size_t count) {
  std::atomic<int> chunks{0};
  std::atomic<std::size_t> visited{0};
  forChunks(count, [&](std::size_t begin, std::size_t end) {
    ++chunks;
    visited += end - begin;
  });
  EXPECT_EQ(visited.load(), count);
  return chunks;
}

TEST(ForChunks, AThreadLimitCapsTheChunksOnItsThreadAndEndsWithIt) {
  const std::size_t count = std::size_t{1} << 22;  // 64 grains
  const int unlimited = chunksOf(count);
  EXPECT_GE(unlimited, 1);
  {
    const ChunkThreadLimit two(2);
    EXPECT_EQ(chunksOf(count), std::min(unlimited, 2));
    {
      const ChunkThreadLimit one(1);
      EXPECT_EQ(chunksOf(count), 1);
      // Another thread is not limited by this one's limit.
      int elsewhere = 0;
      std::thread([&] { elsewhere = chunksOf(count); }).join();
      EXPECT_EQ(elsewhere, unlimited);
    }
    EXPECT_EQ(chunksOf(count), std::min(unlimited, 2));
    const ChunkThreadLimit none(0);  // at least one
    EXPECT_EQ(chunksOf(count), 1);
  }
  EXPECT_EQ(chunksOf(count), unlimited);
}

}  // namespace
}  // namespace sandstorm
