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

PhysicsInputs inputs(const VectorField& f) {
  PhysicsInputs in;
  in.field = &f;
  in.settings.integrator = Integrator::Euler;  // the particles': the streamlines ignore it
  return in;
}

StreamlineSettings lineRake(glm::vec3 from, glm::vec3 to, int seeds,
                            StreamIntegrator method = StreamIntegrator::RK4) {
  StreamlineSettings s;
  s.enabled = true;
  s.integrator = method;
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
      traceStreamlines(lineRake({2, 0, 1}, {2, 0, 1}, 1, StreamIntegrator::Euler), inputs(f));
  ASSERT_EQ(euler.size(), 1u);
  EXPECT_GT(glm::length(glm::vec2(euler[0].points.back().position)), 2.01f);
}

// The streamlines' default, adaptive RK45 within streamlines.tolerance: on
// circles of every size it stays within the tolerance's reach of the analytic
// radius, shortening its steps on the tight ones, where RK4 at the same
// longest step drifts off.
TEST(StreamlineTracer, TheDefaultRk45HoldsTheCircleAndShortensItsStepsWhereItBends) {
  EXPECT_EQ(StreamlineSettings{}.integrator, StreamIntegrator::RK45);
  const VectorField f = bake(Spin(), Box{{-4, -4, 0}, {4, 4, 2}}, {9, 9, 3});
  for (const float r : {0.02f, 1.0f, 3.0f}) {
    SCOPED_TRACE(r);
    StreamlineSettings rake = lineRake({r, 0, 1}, {r, 0, 1}, 1, StreamIntegrator::RK45);
    rake.step = 0.05f;
    rake.length = 5.0f;
    const auto lines = traceStreamlines(rake, inputs(f));
    ASSERT_EQ(lines.size(), 1u);
    const std::vector<StreamlinePoint>& p = lines[0].points;
    float worst = 0.0f, shortest = 1.0f, longest = 0.0f, arc = 0.0f;
    for (std::size_t i = 0; i < p.size(); ++i) {
      worst = std::max(worst, std::abs(glm::length(glm::vec2(p[i].position)) - r));
      if (i > 0) {
        const float chord = glm::length(p[i].position - p[i - 1].position);
        shortest = std::min(shortest, chord);
        longest = std::max(longest, chord);
        // The arc each chord cuts from the circle: the length integrated.
        if (int(i) > lines[0].seedIndex)
          arc += 2.0f * r * std::asin(std::min(1.0f, 0.5f * chord / r));
      }
    }
    EXPECT_LT(worst, 2e-5f);
    EXPECT_LE(longest, rake.step * 1.0001f);
    EXPECT_NEAR(arc, 5.0f, 5e-3f);
    if (r < 0.05f) {
      EXPECT_LT(shortest, 0.5f * rake.step);
      StreamlineSettings fixed = rake;
      fixed.integrator = StreamIntegrator::RK4;
      float drift = 0.0f;
      const auto fixedLines = traceStreamlines(fixed, inputs(f));
      ASSERT_EQ(fixedLines.size(), 1u);
      for (const StreamlinePoint& q : fixedLines[0].points)
        drift = std::max(drift, std::abs(glm::length(glm::vec2(q.position)) - r));
      EXPECT_GT(drift, 10.0f * worst) << "RK4 at the longest step should drift on radius " << r;
    } else {
      EXPECT_GT(shortest, 0.9f * rake.step);  // gentle bends: the longest step throughout
    }
  }
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
