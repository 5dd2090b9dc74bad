// PageBuffer gives back whole pages at its front and keeps the rest intact.
#include "core/util/page_buffer.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <utility>

namespace sandstorm {
namespace {

TEST(PageBuffer, GivesBackWholePagesBeforeAnOffsetAndKeepsTheRest) {
  const std::size_t page = std::size_t(sysconf(_SC_PAGESIZE));
  PageBuffer b(10 * page + 5, "test");
  ASSERT_EQ(b.size(), 10 * page + 5);
  for (std::size_t i = 0; i < b.size(); ++i)
    b.data()[i] = char(i % 251 + 1);
  EXPECT_EQ(b.releaseBefore(3 * page + 7), 3 * page);  // whole pages only
  EXPECT_EQ(b.releaseBefore(page), 3 * page);          // never backwards
  EXPECT_EQ(b.released(), 3 * page);
  for (std::size_t i = 3 * page; i < b.size(); ++i)
    ASSERT_EQ(b.data()[i], char(i % 251 + 1)) << i;
  EXPECT_EQ(b.data()[0], 0);  // given back: zero, as documented
  PageBuffer moved = std::move(b);
  EXPECT_EQ(moved.released(), 3 * page);
  EXPECT_EQ(moved.size(), 10 * page + 5);
  EXPECT_EQ(b.size(), 0u);
}

}  // namespace
}  // namespace sandstorm
