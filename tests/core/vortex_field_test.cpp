#include "core/field/vortex_field.h"

#include <gtest/gtest.h>

namespace sandstorm {
namespace {

TEST(VortexField, SpinsPullsAndLiftsAsTheEquationSays) {
  VortexParams p;
  p.range = 4.0f;
  p.core = 0.5f;
  p.spin = 6.0f;
  p.pull = 2.0f;
  p.up = 1.0f;
  const VortexField f(p);
  // At (2, 0, 1): outward is +x, around is +y, falloff = (4 - 2) / 4.
  const glm::vec3 v = f.evaluate({2.0f, 0.0f, 1.0f});
  EXPECT_NEAR(v.x, 0.5f * -2.0f, 1e-6f);
  EXPECT_NEAR(v.y, 0.5f * 6.0f, 1e-6f);
  EXPECT_NEAR(v.z, 0.5f * 1.0f, 1e-6f);
}

TEST(VortexField, IsContinuousOnTheAxisAndZeroOutside) {
  const VortexField f(VortexParams{});
  const glm::vec3 axis = f.evaluate({0, 0, 1});
  EXPECT_FLOAT_EQ(axis.x, 0.0f);
  EXPECT_FLOAT_EQ(axis.y, 0.0f);
  EXPECT_GT(axis.z, 0.0f);
  const glm::vec3 nearAxis = f.evaluate({1e-3f, 0, 1});
  EXPECT_LT(glm::length(glm::vec2(nearAxis)), 0.05f);
  EXPECT_EQ(f.evaluate({10, 0, 1}), glm::vec3(0.0f));   // beyond range
  EXPECT_EQ(f.evaluate({1, 0, -1}), glm::vec3(0.0f));   // below the base
  EXPECT_EQ(f.evaluate({1, 0, 100}), glm::vec3(0.0f));  // above the top
}

TEST(VortexField, NegativeSpinTurnsTheOtherWay) {
  VortexParams p;
  const glm::vec3 a = VortexField(p).evaluate({1.5f, 0, 1});
  p.spin = -p.spin;
  const glm::vec3 b = VortexField(p).evaluate({1.5f, 0, 1});
  EXPECT_FLOAT_EQ(a.y, -b.y);
  EXPECT_FLOAT_EQ(a.x, b.x);
}

}  // namespace
}  // namespace sandstorm
