// forChunks: every index of the range exactly once, in contiguous chunks,
// whatever the count against the grain (none, fewer than a grain, many).
#include <gtest/gtest.h>

#include <atomic>
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
