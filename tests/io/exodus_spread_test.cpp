// Decomposed Exodus run names: what is one ("out.e.4.0") and what only
// looks like one.
#include <gtest/gtest.h>

#include "core/io/exodus_spread.h"

namespace sandstorm {
namespace {

TEST(ExodusSpread, NamesOfARankAndNamesThatAreNot) {
  const auto run = parseExodusSpreadName("dir/out.e.16.03");
  ASSERT_TRUE(run);
  EXPECT_EQ(run->base, std::filesystem::path("dir/out.e"));
  EXPECT_EQ(run->count, 16);
  EXPECT_EQ(run->rank, 3);
  for (const char* name : {"out.e", "out.e.4", "out.e.1.0", "out.e.4.4", "out.e.4.x", "out.e..0",
                           "out.e.4.", ".4.0", "out.e.9999999.0", "out.e.70000.1", "out.e.-4.0"})
    EXPECT_FALSE(parseExodusSpreadName(name)) << name;
}

}  // namespace
}  // namespace sandstorm
