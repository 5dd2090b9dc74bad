// Streamlines against their analytic shapes: circles in solid-body rotation,
// straight lines in a uniform wind.
#include "core/flow/streamline_tracer.h"

#include <gtest/gtest.h>

#include "core/field/analytic_field.h"

namespace sandstorm {
namespace {

struct Spin final : AnalyticField {  // solid-body rotation about the z axis, 1 rad/s
  glm::vec3 evaluate(const glm::vec3& p) const override { return {-p.y, p.x, 0.0f}; }
};
struct Wind final : AnalyticField {
  glm::vec3 evaluate(const glm::vec3&) const override { return {3.0f, 4.0f, 0.0f}; }
};
struct Still final : AnalyticField {
  glm::vec3 evaluate(const glm::vec3&) const override { return glm::vec3(0.0f); }
};

PhysicsInputs inputs(const VectorField& f, Integrator integrator = Integrator::RK4) {
  PhysicsInputs in;
  in.field = &f;
  in.settings.integrator = integrator;
  return in;
}

StreamlineSettings lineRake(glm::vec3 from, glm::vec3 to, int seeds) {
  StreamlineSettings s;
  s.enabled = true;
  s.from = from;
  s.to = to;
  s.seeds = seeds;
  s.step = 0.05f;
  s.length = 12.0f;
  return s;
}

TEST(StreamlineTracer, StreamlinesOfSolidBodyRotationAreCircles) {
  // Linear in x and y, so the baked grid interpolates the rotation exactly.
  const VectorField f = bake(Spin(), Box{{-4, -4, 0}, {4, 4, 2}}, {9, 9, 3});
  const auto lines = traceStreamlines(lineRake({1, 0, 1}, {3, 0, 1}, 3), inputs(f));
  ASSERT_EQ(lines.size(), 3u);
  for (const Streamline& line : lines) {
    const float r = glm::length(glm::vec2(line.points[std::size_t(line.seedIndex)].position));
    // 12 m each way: about once round (2 pi r <= 18.9 m) or more.
    EXPECT_EQ(line.points.size(), 2u * 240u + 1u);
    float worst = 0.0f;
    for (const StreamlinePoint& p : line.points) {
      worst = std::max(worst, std::abs(glm::length(glm::vec2(p.position)) - r));
      EXPECT_FLOAT_EQ(p.position.z, 1.0f);
    }
    EXPECT_LT(worst, 1e-4f) << "radius " << r;
  }
}

TEST(StreamlineTracer, EulerDriftsOutwardWhereRk4StaysOnTheCircle) {
  const VectorField f = bake(Spin(), Box{{-4, -4, 0}, {4, 4, 2}}, {9, 9, 3});
  const auto euler =
      traceStreamlines(lineRake({2, 0, 1}, {2, 0, 1}, 1), inputs(f, Integrator::Euler));
  ASSERT_EQ(euler.size(), 1u);
  EXPECT_GT(glm::length(glm::vec2(euler[0].points.back().position)), 2.01f);
}

TEST(StreamlineTracer, AUniformWindGivesAStraightLineToTheFieldsEdge) {
  const VectorField f = bake(Wind(), Box{{-5, -5, 0}, {5, 5, 2}}, {2, 2, 2});
  StreamlineSettings rake = lineRake({0, 0, 1}, {0, 0, 1}, 1);
  rake.length = 100.0f;
  const auto lines = traceStreamlines(rake, inputs(f));
  ASSERT_EQ(lines.size(), 1u);
  const glm::vec3 along(0.6f, 0.8f, 0.0f);
  for (const StreamlinePoint& p : lines[0].points) {
    const glm::vec3 d = p.position - glm::vec3(0, 0, 1);
    EXPECT_NEAR(glm::length(d - glm::dot(d, along) * along), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(p.velocity), 5.0f, 1e-5f);
  }
  // Forward it leaves through y = 5 after 6.25 m, backward through y = -5.
  EXPECT_NEAR(lines[0].points.back().position.y, 5.0f, 0.05f);
  EXPECT_NEAR(lines[0].points.front().position.y, -5.0f, 0.05f);
  EXPECT_LE(lines[0].points.back().position.y, 5.0f);
}

TEST(StreamlineTracer, StillAirAndSeedsOutsideTheFieldGiveNoLine) {
  const VectorField still = bake(Still(), Box{{-1, -1, 0}, {1, 1, 1}}, {2, 2, 2});
  const auto lines = traceStreamlines(lineRake({0, 0, 0.5f}, {5, 0, 0.5f}, 2), inputs(still));
  ASSERT_EQ(lines.size(), 1u);  // the seed at x = 5 lies outside
  EXPECT_EQ(lines[0].points.size(), 1u);
}

TEST(StreamlineTracer, APlaneRakeSeedsAGridAndAPlacedFieldMovesItsLines) {
  StreamlineSettings rake = lineRake({0, 0, 0}, {1, 0, 0}, 4);
  rake.shape = RakeShape::Plane;
  rake.across = {0, 0, 2};
  const auto seeds = rakeSeeds(rake);
  ASSERT_EQ(seeds.size(), 16u);
  EXPECT_EQ(seeds[5], glm::vec3(1.0f / 3.0f, 0.0f, 2.0f / 3.0f));
  // A rotation scaled by 2 and moved by (10, 0, 0): circles about x = 10.
  const VectorField f = bake(Spin(), Box{{-4, -4, 0}, {4, 4, 2}}, {9, 9, 3});
  PhysicsInputs in = inputs(f);
  in.placement.offset = {10, 0, 0};
  in.placement.scale = 2.0f;
  const auto lines = traceStreamlines(lineRake({12, 0, 1}, {12, 0, 1}, 1), in);
  ASSERT_EQ(lines.size(), 1u);
  for (const StreamlinePoint& p : lines[0].points)
    EXPECT_NEAR(glm::length(glm::vec2(p.position - glm::vec3(10, 0, 0))), 2.0f, 2e-4f);
}

}  // namespace
}  // namespace sandstorm
