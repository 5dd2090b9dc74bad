// The analytic fields against their equations.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/field/analytic_field_factory.h"
#include "core/field/curl_noise_field.h"
#include "core/field/downwash_field.h"
#include "core/field/gravity_point_field.h"
#include "core/field/sphere_flow_field.h"
#include "core/field/sum_field.h"
#include "core/field/vortex_field.h"
#include "core/field/wind_field.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

constexpr double kPi = std::numbers::pi;

// Central-difference divergence, in double around a float field.
double divergence(const AnalyticField& f, const glm::vec3& p, float h) {
  double d = 0.0;
  for (int a = 0; a < 3; ++a) {
    glm::vec3 e(0.0f);
    e[a] = h;
    d += (double(f.evaluate(p + e)[a]) - double(f.evaluate(p - e)[a])) / (2.0 * h);
  }
  return d;
}

TEST(GravityPointField, FollowsTheThesisEquation) {
  GravityPointParams q;
  q.center = {1, 2, 3};
  q.range = 4.0f;
  q.power = 2.0f;
  const GravityPointField f(q);
  // At distance 1 along +x from the centre: pulled back along -x with 2 * (4 - 1) / 4.
  const glm::vec3 v = f.evaluate({2, 2, 3});
  EXPECT_NEAR(v.x, -1.5f, 1e-6f);
  EXPECT_NEAR(v.y, 0.0f, 1e-6f);
  EXPECT_NEAR(v.z, 0.0f, 1e-6f);
  // Diagonal point at distance 3: direction (c - p) / 3, size 2 * 1 / 4.
  const glm::vec3 p(1 + 1, 2 + 2, 3 - 2);
  const glm::vec3 w = f.evaluate(p);
  const glm::vec3 expected = (q.center - p) / 3.0f * (2.0f * (4.0f - 3.0f) / 4.0f);
  EXPECT_NEAR(glm::length(w - expected), 0.0f, 1e-6f);
  EXPECT_EQ(f.evaluate({10, 2, 3}), glm::vec3(0.0f));  // beyond range
  EXPECT_EQ(f.evaluate(q.center), glm::vec3(0.0f));    // no direction at the centre
  q.power = -2.0f;
  EXPECT_NEAR(GravityPointField(q).evaluate({2, 2, 3}).x, 1.5f, 1e-6f);  // repels
}

TEST(WindField, IsPowerAlongTheDirectionPlusBoundedNoise) {
  WindParams q;
  q.direction = {0, 3, 4};
  q.power = 5.0f;
  q.noise = 0.0f;
  EXPECT_NEAR(glm::length(WindField(q).evaluate({7, 8, 9}) - glm::vec3(0, 3, 4)), 0.0f, 1e-6f);
  q.noise = 0.5f;
  const WindField noisy(q);
  double mean = 0.0;
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 v = noisy.evaluate({i * 0.37f, i * 0.11f, i * 0.23f});
    const glm::vec3 r = v - glm::vec3(0, 3, 4);
    EXPECT_LE(std::abs(r.x), 0.5f * 1.01f);
    EXPECT_LE(std::abs(r.y), 0.5f * 1.01f);
    EXPECT_LE(std::abs(r.z), 0.5f * 1.01f);
    mean += r.x;
  }
  EXPECT_LT(std::abs(mean / 200.0), 0.25);
  // Smooth: nearby points differ little.
  const glm::vec3 a = noisy.evaluate({1.0f, 1.0f, 1.0f}), b = noisy.evaluate({1.001f, 1.0f, 1.0f});
  EXPECT_LT(glm::length(a - b), 0.01f);
}

TEST(CurlNoiseField, IsDivergenceFree) {
  CurlNoiseParams q;
  q.scale = 1.5f;
  q.amplitude = 2.0f;
  const CurlNoiseField f(q);
  double worstDiv = 0.0, typicalGrad = 0.0;
  for (int i = 0; i < 50; ++i) {
    const glm::vec3 p(0.31f * i - 4.0f, 0.17f * i + 0.05f, -0.23f * i + 1.0f);
    worstDiv = std::max(worstDiv, std::abs(divergence(f, p, 1e-2f)));
    // The size of one velocity gradient, to judge the divergence against.
    typicalGrad += std::abs(
        (f.evaluate(p + glm::vec3(1e-2f, 0, 0)).y - f.evaluate(p - glm::vec3(1e-2f, 0, 0)).y) /
        2e-2);
  }
  typicalGrad /= 50.0;
  EXPECT_GT(typicalGrad, 0.1);                     // the field does vary
  EXPECT_LT(worstDiv, 1e-3 * typicalGrad * 10.0);  // and its divergence is rounding
}

TEST(SphereFlowField, SlipsAlongTheSphereAndMatchesTheTextbook) {
  SphereFlowParams q;
  q.center = {1, 1, 1};
  q.radius = 2.0f;
  q.speed = 3.0f;
  q.direction = {1, 0, 0};
  const SphereFlowField f(q);
  // Stagnation points up- and downstream; 1.5 U at the equator.
  EXPECT_NEAR(glm::length(f.evaluate(q.center + glm::vec3(-2, 0, 0))), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(f.evaluate(q.center + glm::vec3(2, 0, 0))), 0.0f, 1e-5f);
  const glm::vec3 equator = f.evaluate(q.center + glm::vec3(0, 0, 2));
  EXPECT_NEAR(equator.x, 4.5f, 1e-5f);
  EXPECT_NEAR(equator.z, 0.0f, 1e-5f);
  // No flow through the surface anywhere.
  for (int i = 0; i < 20; ++i) {
    const double th = 0.3 * i, ph = 0.7 * i;
    const glm::vec3 n(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
    EXPECT_NEAR(glm::dot(f.evaluate(q.center + 2.0001f * n), n), 0.0f, 1e-3f);
  }
  // The free stream far away, and divergence-free outside.
  EXPECT_NEAR(glm::length(f.evaluate({500, 0, 0}) - glm::vec3(3, 0, 0)), 0.0f, 1e-4f);
  EXPECT_LT(std::abs(divergence(f, {4, 2.5f, -1}, 1e-2f)), 1e-3);
  // The Mali source: Q / (4 pi r^2) radially at distance r >> eps.
  q.speed = 0.0f;
  q.source = 10.0f;
  q.epsilon = 0.0f;
  const glm::vec3 s = SphereFlowField(q).evaluate(q.center + glm::vec3(0, 3, 0));
  EXPECT_NEAR(s.y, 10.0 / (4.0 * kPi * 9.0), 1e-6);
  EXPECT_NEAR(s.x, 0.0f, 1e-7f);
  EXPECT_EQ(SphereFlowField(q).evaluate(q.center), glm::vec3(0.0f));  // inside: zero
}

TEST(DownwashField, BlowsTheMomentumTheorySpeedThroughTheDisc) {
  DownwashParams q;
  q.hub = {3, -2, 12};
  q.radius = 5.0f;
  q.thrust = 19620.0f;  // a 2-tonne helicopter in hover
  q.density = 1.225f;
  q.ground = 0.0f;
  q.groundLayer = 4.0f;
  const DownwashField f(q);
  const double vh = std::sqrt(19620.0 / (2.0 * 1.225 * kPi * 25.0));
  EXPECT_NEAR(f.hoverInducedSpeed(), vh, 1e-4);
  const glm::vec3 disc = f.evaluate(q.hub);
  EXPECT_NEAR(disc.z, -vh, 1e-4);
  EXPECT_NEAR(glm::length(glm::vec2(disc)), 0.0f, 1e-6f);
}

TEST(DownwashField, ConservesTheDiscFlowInColumnAndWallJet) {
  DownwashParams q;
  q.hub = {0, 0, 15};
  q.radius = 4.0f;
  q.thrust = 15000.0f;
  q.groundLayer = 3.0f;
  const DownwashField f(q);
  const double Q = kPi * 16.0 * f.hoverInducedSpeed();
  // Downward flux through the horizontal plane 8 m below the disc.
  double down = 0.0;
  const double dr = 0.01;
  for (double r = dr / 2; r < 40.0; r += dr)
    down += -f.evaluate({float(r), 0.0f, 7.0f}).z * 2.0 * kPi * r * dr;
  EXPECT_NEAR(down / Q, 1.0, 1e-3);
  // Outward flux through the cylinder of radius 20 m around the axis.
  double out = 0.0;
  const double dz = 0.005;
  for (double z = dz / 2; z < 15.0; z += dz)
    out += f.evaluate({20.0f, 0.0f, float(z)}).x * 2.0 * kPi * 20.0 * dz;
  EXPECT_NEAR(out / Q, 1.0, 1e-2);
  // Far below a high rotor the column reaches momentum theory's 2 v_h.
  DownwashParams high = q;
  high.hub.z = 2000.0f;
  EXPECT_NEAR(
      -DownwashField(high).evaluate({0, 0, 1000}).z / DownwashField(high).hoverInducedSpeed(), 2.0,
      1e-3);
}

TEST(SumField, AddsItsParts) {
  GravityPointParams g;
  WindParams w;
  w.noise = 0.0f;
  SumField sum;
  sum.add(std::make_unique<GravityPointField>(g)).add(std::make_unique<WindField>(w));
  const glm::vec3 p(1, 0.5f, 0);
  const glm::vec3 expected = GravityPointField(g).evaluate(p) + WindField(w).evaluate(p);
  EXPECT_NEAR(glm::length(sum.evaluate(p) - expected), 0.0f, 1e-6f);
  EXPECT_EQ(SumField().evaluate(p), glm::vec3(0.0f));
}

TEST(AnalyticFieldFactory, BuildsEachFieldWithDefaultsAndOverrides) {
  for (const AnalyticFieldSpec& spec : analyticFieldSpecs())
    EXPECT_NO_THROW(makeAnalyticField(spec.name, {})) << spec.name;
  const auto g = makeAnalyticField("gravity", {{"power", -3.0}, {"range", 6.0}, {"center_x", 1.0}});
  GravityPointParams q;
  q.power = -3.0f;
  q.range = 6.0f;
  q.center = {1, 0, 0};
  EXPECT_EQ(g->evaluate({2, 1, 0}), GravityPointField(q).evaluate({2, 1, 0}));
  const auto t = makeAnalyticField("tornado", {{"spin", 9.0}});
  VortexParams v;
  v.spin = 9.0f;
  EXPECT_EQ(t->evaluate({1, 1, 1}), VortexField(v).evaluate({1, 1, 1}));
}

TEST(AnalyticFieldFactory, ListsWhatItKnowsWhenAskedForSomethingElse) {
  test::expectError(
      [] { makeAnalyticField("hurricane", {}); },
      {"hurricane", "tornado", "gravity", "wind", "curl_noise", "sphere_flow", "downwash"});
  test::expectError(
      [] {
        makeAnalyticField("wind", {{"speed", 1.0}});
      },
      {"speed", "power", "noise_scale", "direction_x"});
  test::expectError([] { makeAnalyticField("gravity", {{"range", -1.0}}); }, {"range"});
  test::expectError(
      [] {
        makeAnalyticField("gravity", {{"power", std::nan("")}});
      },
      {"power", "finite"});
}

}  // namespace
}  // namespace sandstorm
