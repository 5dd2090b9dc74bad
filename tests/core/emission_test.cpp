#include "core/sim/emission.h"

#include <gtest/gtest.h>

#include "core/sim/emission_budget.h"

namespace sandstorm {
namespace {

TEST(Emission, MeanRateIsExactOnAverageAtAnyFrameRate) {
  Emitter e;
  e.rate = 1234.5f;
  for (float dt : {1.0f / 60.0f, 1.0f / 144.0f, 0.1f}) {
    double total = 0;
    const int frames = 20000;
    for (int f = 0; f < frames; ++f)
      total += emissionCount(e, dt, Seed::from(9), std::uint32_t(f), 0);
    const double expected = double(e.rate) * dt * frames;
    // Stochastic rounding adds at most a Bernoulli variance of 1/4 per frame.
    EXPECT_NEAR(total, expected, 5.0 * std::sqrt(frames * 0.25)) << "dt " << dt;
  }
}

TEST(Emission, VarianceSpreadsCountsWithinReevesBounds) {
  Emitter e;
  e.rate = 6000.0f;
  e.rateVariance = 3000.0f;
  const float dt = 0.01f;  // mean 60, variance +-30
  std::uint32_t lo = 1000, hi = 0;
  for (std::uint32_t f = 0; f < 5000; ++f) {
    const std::uint32_t n = emissionCount(e, dt, Seed::from(3), f, 0);
    lo = std::min(lo, n);
    hi = std::max(hi, n);
  }
  EXPECT_GE(lo, 30u);
  EXPECT_LE(hi, 91u);
  EXPECT_LT(lo, 35u);  // the whole range is used
  EXPECT_GT(hi, 85u);
}

TEST(Emission, NothingWhileStoppedPausedOrDisabled) {
  ParticleState s;
  s.emitters[0].rate = 1e5f;
  EXPECT_GT(emissionCounts(s, 0.1f, Seed::from(1), 0)[0], 0u);
  s.sim.emitting = false;
  EXPECT_EQ(emissionCounts(s, 0.1f, Seed::from(1), 0)[0], 0u);
  s.sim.emitting = true;
  s.sim.paused = true;
  EXPECT_EQ(emissionCounts(s, 0.1f, Seed::from(1), 0)[0], 0u);
  s.sim.paused = false;
  s.emitters[0].enabled = false;
  EXPECT_EQ(emissionCounts(s, 0.1f, Seed::from(1), 0)[0], 0u);
  s.emitters[0].enabled = true;
  EXPECT_EQ(emissionCounts(s, 0.0f, Seed::from(1), 0)[0], 0u);
}

TEST(EmissionBudget, GrantsEarlierEmittersFirstWithinTheBound) {
  EmissionBudget budget;
  EXPECT_EQ(budget.allocate({10, 20, 30}, 100, 0), (std::vector<std::uint32_t>{10, 20, 30}));
  EXPECT_EQ(budget.allocate({10, 20, 30}, 100, 75), (std::vector<std::uint32_t>{10, 15, 0}));
  budget.recordEmitted(20);  // E(u-1) counts against the bound too
  EXPECT_EQ(budget.allocate({10, 20, 30}, 100, 75), (std::vector<std::uint32_t>{5, 0, 0}));
  EXPECT_EQ(budget.allocate({10, 20, 30}, 50, 75), (std::vector<std::uint32_t>{0, 0, 0}));
}

}  // namespace
}  // namespace sandstorm
