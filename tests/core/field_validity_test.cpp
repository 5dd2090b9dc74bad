// A field's validity mask (points a resampled file had no data for): a cell
// with an invalid corner is outside the field, as the bounds are, for every
// boundary mode; a mask with every point valid is no mask; the mask travels
// with the grid on the cluster's wire.
#include <gtest/gtest.h>

#include "core/sim/frame_packet_codec.h"
#include "core/sim/particle_physics.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

// 1 m/s along +x over 10 m; points at x >= 6 have no data.
VectorField windWithAHole() {
  VectorField f(Box{{0, 0, 0}, {10, 1, 1}}, {11, 2, 2});
  std::vector<std::uint8_t> valid(f.pointCount(), 1);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 11; ++i) {
        f.at(i, j, k) = {1, 0, 0};
        if (i >= 6) valid[f.index(i, j, k)] = 0;
      }
  f.setValidity(valid);
  return f;
}

PhysicsInputs inputs(const VectorField& f, BoundaryMode mode) {
  PhysicsInputs in;
  in.field = &f;
  in.settings.motion = MotionModel::Tracer;
  in.settings.integrator = Integrator::Euler;
  in.settings.boundary = mode;
  in.dt = 0.1f;
  return in;
}

// The time a tracer from x = 1 spends before its cell touches x = 6 (the cell [5, 6]).
TEST(FieldValidity, KillEndsAParticleWhoseCellTouchesTheHole) {
  const VectorField f = windWithAHole();
  EXPECT_EQ(f.invalidCount(), 20u);
  EXPECT_TRUE(f.cellValid({4.9f, 0.5f, 0.5f}));
  EXPECT_FALSE(f.cellValid({5.1f, 0.5f, 0.5f}));
  Particle p{glm::vec4(1.0f, 0.5f, 0.5f, 100.0f), glm::vec4(0.0f)};
  const PhysicsInputs in = inputs(f, BoundaryMode::Kill);
  int steps = 0;
  while (advance(p, in) && steps < 1000)
    ++steps;
  // Its last position lies in the last valid cell; one more step is past x = 5.
  EXPECT_TRUE(f.cellValid(glm::vec3(p.position())));
  EXPECT_FALSE(f.cellValid(glm::vec3(p.position()) + glm::vec3(0.1f, 0.0f, 0.0f)));
  EXPECT_GT(p.position().x, 4.85f);
  EXPECT_NEAR(float(steps), 40.0f, 1.0f);
}

TEST(FieldValidity, ClampHoldsAParticleAtTheLastValidPlace) {
  const VectorField f = windWithAHole();
  Particle p{glm::vec4(1.0f, 0.5f, 0.5f, 100.0f), glm::vec4(0.0f)};
  const PhysicsInputs in = inputs(f, BoundaryMode::Clamp);
  for (int i = 0; i < 100; ++i)
    ASSERT_TRUE(advance(p, in));
  EXPECT_LT(p.position().x, 5.0f);
  EXPECT_GT(p.position().x, 4.8f);
  EXPECT_TRUE(f.cellValid(glm::vec3(p.position())));
}

TEST(FieldValidity, WrapHasNowhereToSendIt) {
  const VectorField f = windWithAHole();
  Particle p{glm::vec4(4.95f, 0.5f, 0.5f, 100.0f), glm::vec4(0.0f)};
  EXPECT_FALSE(advance(p, inputs(f, BoundaryMode::Wrap)));
}

TEST(FieldValidity, AMaskWithEveryPointValidIsNoMask) {
  VectorField f(Box{{0, 0, 0}, {1, 1, 1}}, {2, 2, 2});
  f.setValidity(std::vector<std::uint8_t>(8, 1));
  EXPECT_FALSE(f.hasValidity());
  EXPECT_THROW(f.setValidity(std::vector<std::uint8_t>(7, 1)), Error);
}

TEST(FieldValidity, TheMaskTravelsWithTheGrid) {
  const VectorField f = windWithAHole();
  const VectorField g = decodeField(encodeField(f));
  ASSERT_TRUE(g.hasValidity());
  EXPECT_TRUE(std::equal(f.validity().begin(), f.validity().end(), g.validity().begin(),
                         g.validity().end()));
  EXPECT_NE(fieldHash(f),
            fieldHash(VectorField(f.bounds(), f.dims(),
                                  std::vector<glm::vec3>(f.values().begin(), f.values().end()))));
}

}  // namespace
}  // namespace sandstorm
