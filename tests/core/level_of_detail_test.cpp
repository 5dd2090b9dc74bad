// Level of detail (Reeves): coverage of the view, the frame-time budget, and
// the main context scaling emission so every wall gets the same counts.
#include "core/sim/level_of_detail.h"

#include <gtest/gtest.h>

#include <numeric>

#include "core/sim/main_context.h"

namespace sandstorm {
namespace {

Viewer headAt(glm::vec3 position) {
  Viewer v;
  v.head.position = position;
  return v;
}

TEST(LevelOfDetail, CoverageFallsWithDistanceAndIsFullInside) {
  const Box box{{-1, -1, -1}, {1, 1, 1}};  // bounding sphere radius sqrt(3)
  EXPECT_FLOAT_EQ(viewCoverage(box, {}, headAt({0, 0, 0})), 1.0f);
  const float near = viewCoverage(box, {}, headAt({0, -4, 0}));
  const float far = viewCoverage(box, {}, headAt({0, -40, 0}));
  EXPECT_LT(far, near);
  EXPECT_GT(far, 0.0f);
  // Far away the solid angle goes as pi r^2 / d^2: ten times the distance, a hundredth.
  const float farther = viewCoverage(box, {}, headAt({0, -400, 0}));
  EXPECT_NEAR(far / farther, 100.0f, 1.0f);
  // Placement scales the system: twice the size looks like half the distance.
  FieldPlacement doubled;
  doubled.scale = 2.0f;
  EXPECT_NEAR(viewCoverage(box, doubled, headAt({0, -80, 0})), far, 1e-3f * far + 1e-7f);
}

TEST(LevelOfDetail, OffMeansFullEmission) {
  LevelOfDetail lod;
  SimSettings s;
  EXPECT_EQ(lod.update(s, 0.0f, 100.0), 1.0f);
}

TEST(LevelOfDetail, SmallCoverageLowersEmissionDownToTheMinimum) {
  LevelOfDetail lod;
  SimSettings s;
  s.lod = true;
  s.lodCoverage = 0.2f;
  s.lodMinScale = 0.1f;
  EXPECT_FLOAT_EQ(lod.update(s, 0.5f, std::nullopt), 1.0f);
  EXPECT_FLOAT_EQ(lod.update(s, 0.1f, std::nullopt), 0.5f);
  EXPECT_FLOAT_EQ(lod.update(s, 0.001f, std::nullopt), 0.1f);
}

TEST(LevelOfDetail, FramesOverBudgetLowerEmissionAndItRecoversUnderBudget) {
  LevelOfDetail lod;
  SimSettings s;
  s.lod = true;
  s.lodBudgetMs = 16.0f;
  s.lodMinScale = 0.05f;
  EXPECT_FLOAT_EQ(lod.update(s, 1.0f, 12.0), 1.0f);
  // 32 ms frames: twice the budget halves emission, frame after frame, down to the minimum.
  EXPECT_FLOAT_EQ(lod.update(s, 1.0f, 32.0), 0.5f);
  EXPECT_FLOAT_EQ(lod.update(s, 1.0f, 32.0), 0.25f);
  for (int i = 0; i < 10; ++i)
    lod.update(s, 1.0f, 32.0);
  EXPECT_FLOAT_EQ(lod.scale(), 0.05f);
  // Within 90-100% of the budget it holds; below, it climbs back 5% a frame.
  EXPECT_FLOAT_EQ(lod.update(s, 1.0f, 15.0), 0.05f);
  float last = lod.scale();
  for (int i = 0; i < 100; ++i) {
    lod.update(s, 1.0f, 10.0);
    EXPECT_GE(lod.scale(), last);
    last = lod.scale();
  }
  EXPECT_FLOAT_EQ(last, 1.0f);
}

TEST(LevelOfDetail, TheMainContextScalesTheCountsItShipsToEveryWall) {
  ParticleState state;
  state.emitters[0].rate = 60000.0f;
  state.emitters[0].rateVariance = 0.0f;
  MainContext::Options options;
  options.fixedDt = 1.0f / 60.0f;
  auto field = std::make_shared<VectorField>(VectorField(Box{{-1, -1, 0}, {1, 1, 2}}, {2, 2, 2}));
  MainContext main(state, FieldUpdate{.field = field}, options);
  main.setViewer(headAt({0, -200, 1}));  // the system is a speck
  const FramePacket before = main.next();
  EXPECT_EQ(before.lodScale, 1.0f);
  EXPECT_EQ(before.emission[0], 1000u);
  main.set("sim.lod", true);
  main.set("sim.lod_min_scale", 0.25f);
  const FramePacket after = main.next();
  EXPECT_FLOAT_EQ(after.lodScale, 0.25f);
  EXPECT_EQ(after.emission[0], 250u);
  // The frame-time budget: reported frames of twice the budget halve it again... down to the
  // minimum.
  main.set("sim.lod_coverage", 0.0f);  // coverage no longer limits
  main.set("sim.lod_budget_ms", 10.0f);
  main.reportFrameTime(20.0);
  EXPECT_FLOAT_EQ(main.next().lodScale, 0.5f);
  EXPECT_FLOAT_EQ(main.next().lodScale, 0.25f);
}

}  // namespace
}  // namespace sandstorm
