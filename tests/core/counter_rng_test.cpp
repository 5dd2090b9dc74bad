#include "core/sim/counter_rng.h"

#include <gtest/gtest.h>

#include <set>

namespace sandstorm {
namespace {

TEST(CounterRng, IsAPureFunctionOfItsKey) {
  const Seed seed = Seed::from(0x123456789abcdefull);
  EXPECT_EQ(randomBits(seed, 7, 2, 99, RngStream::kBirth),
            randomBits(seed, 7, 2, 99, RngStream::kBirth));
  EXPECT_NE(randomBits(seed, 7, 2, 99, RngStream::kBirth),
            randomBits(seed, 7, 2, 99, RngStream::kVelocityBall));
  EXPECT_NE(randomBits(seed, 7, 2, 99, RngStream::kBirth),
            randomBits(seed, 8, 2, 99, RngStream::kBirth));
  EXPECT_NE(randomBits(seed, 7, 2, 99, RngStream::kBirth),
            randomBits(seed, 7, 3, 99, RngStream::kBirth));
  EXPECT_NE(randomBits(seed, 7, 2, 99, RngStream::kBirth),
            randomBits(Seed::from(5), 7, 2, 99, RngStream::kBirth));
}

TEST(CounterRng, KnownValueOfPcg4d) {
  // pcg4d(0,0,0,0): every lane starts at 1013904223 (Jarzynski & Olano's constants).
  const glm::uvec4 v = pcg4d(glm::uvec4(0u));
  glm::uvec4 e(1013904223u);
  e.x += e.y * e.w;
  e.y += e.z * e.x;
  e.z += e.x * e.y;
  e.w += e.y * e.z;
  e ^= e >> 16u;
  e.x += e.y * e.w;
  e.y += e.z * e.x;
  e.z += e.x * e.y;
  e.w += e.y * e.z;
  EXPECT_EQ(v, e);
}

TEST(CounterRng, UniformNumbersAreUniform) {
  // Chi-square over 16 bins per lane, 64k samples: the 99.9% critical value for 15 dof is 37.7.
  constexpr int kBins = 16, kSamples = 1 << 16;
  for (int lane = 0; lane < 4; ++lane) {
    int bins[kBins] = {};
    for (int i = 0; i < kSamples; ++i) {
      const float u =
          randomUniform(Seed::from(42), 3, 1, std::uint32_t(i), RngStream::kBirth)[lane];
      ASSERT_GE(u, 0.0f);
      ASSERT_LT(u, 1.0f);
      ++bins[int(u * kBins)];
    }
    double chi2 = 0;
    for (int b : bins) {
      const double expected = double(kSamples) / kBins;
      chi2 += (b - expected) * (b - expected) / expected;
    }
    EXPECT_LT(chi2, 37.7) << "lane " << lane;
  }
}

TEST(CounterRng, NeighbouringIndicesDoNotCollide) {
  std::set<std::uint32_t> seen;
  for (std::uint32_t i = 0; i < 10000; ++i)
    seen.insert(randomBits(Seed::from(1), 0, 0, i, RngStream::kBirth).x);
  EXPECT_GT(seen.size(), 9990u);
}

}  // namespace
}  // namespace sandstorm
