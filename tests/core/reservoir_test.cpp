// Reservoir: bounded memory, every value kept until it is full, then a uniform
// sample: the median of a sample of 10^6 values 0..10^6-1 is near 5·10^5, and
// each tenth of the run holds about a tenth of the sample.
#include "core/util/reservoir.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

namespace sandstorm {
namespace {

TEST(Reservoir, KeepsEverythingUntilFullInOrder) {
  Reservoir<int> r(5);
  for (int i = 0; i < 4; ++i)
    r.offer(i);
  EXPECT_EQ(r.values(), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(r.seen(), 4u);
}

TEST(Reservoir, ALongRunIsSampledUniformlyInBoundedMemory) {
  constexpr int kValues = 1000000;
  constexpr std::size_t kCapacity = 4096;
  Reservoir<int> r(kCapacity);
  for (int i = 0; i < kValues; ++i)
    r.offer(i);
  EXPECT_EQ(r.seen(), std::uint64_t(kValues));
  ASSERT_EQ(r.values().size(), kCapacity);
  std::vector<int> v = r.values();
  std::sort(v.begin(), v.end());
  // The sample median of 4096 uniform draws is within 3% of the range of the true one.
  EXPECT_NEAR(v[kCapacity / 2], kValues / 2, kValues * 0.03);
  EXPECT_NEAR(v[kCapacity * 95 / 100], kValues * 0.95, kValues * 0.03);
  std::array<int, 10> tenths{};
  for (int x : v)
    ++tenths[std::size_t(x / (kValues / 10))];
  for (int n : tenths)
    EXPECT_NEAR(n, int(kCapacity / 10), 90);                   // ~4.5 standard deviations
  EXPECT_EQ(std::adjacent_find(v.begin(), v.end()), v.end());  // no value twice
}

}  // namespace
}  // namespace sandstorm
