// Integration accuracy against analytic solutions. The fields used are linear
// in space, which trilinear sampling reproduces exactly, so every difference
// measured here is the integrator's own.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "core/field/analytic_field.h"
#include "core/sim/particle_physics.h"

namespace sandstorm {
namespace {

struct Rotation final : AnalyticField {
  float omega;
  explicit Rotation(float w) : omega(w) {}
  glm::vec3 evaluate(const glm::vec3& p) const override {
    return omega * glm::vec3(-p.y, p.x, 0.0f);
  }
};

struct Constant final : AnalyticField {
  glm::vec3 value;
  explicit Constant(glm::vec3 v) : value(v) {}
  glm::vec3 evaluate(const glm::vec3&) const override { return value; }
};

Particle run(const VectorField& field, MotionModel motion, Integrator integrator, float dt,
             int steps, glm::vec3 x0, glm::vec3 v0 = glm::vec3(0), glm::vec3 gravity = glm::vec3(0),
             float tau = 1.0f) {
  PhysicsInputs in;
  in.field = &field;
  in.settings.motion = motion;
  in.settings.integrator = integrator;
  in.settings.gravity = gravity;
  in.settings.dragTime = tau;
  in.settings.groundCollision = false;
  in.dt = dt;
  Particle p{glm::vec4(x0, 1e6f), glm::vec4(v0, 1e6f)};
  for (int i = 0; i < steps; ++i)
    EXPECT_TRUE(advance(p, in));
  return p;
}

// One step of each scheme multiplies x + iy by its amplification factor g(i w h).
std::complex<double> amplification(Integrator integrator, double theta) {
  const std::complex<double> z(0.0, theta);
  switch (integrator) {
    case Integrator::Euler:
      return 1.0 + z;
    case Integrator::RK2:
      return 1.0 + z + z * z / 2.0;
    case Integrator::RK4:
      return 1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0;
  }
  return 0;
}

class SolidBodyRotation : public ::testing::TestWithParam<Integrator> {};

TEST_P(SolidBodyRotation, MatchesTheSchemesExactAmplification) {
  const float omega = 1.0f, dt = 0.05f;
  const int steps = int(std::round(2 * M_PI / (omega * dt)));  // about one revolution
  const VectorField field = bake(Rotation(omega), Box{{-2, -2, -1}, {2, 2, 1}}, {9, 9, 3});
  const Particle p = run(field, MotionModel::Tracer, GetParam(), dt, steps, {1.0f, 0.0f, 0.0f});
  const std::complex<double> expected = std::pow(amplification(GetParam(), omega * dt), steps);
  EXPECT_NEAR(p.position().x, expected.real(), 2e-5);
  EXPECT_NEAR(p.position().y, expected.imag(), 2e-5);
  EXPECT_FLOAT_EQ(p.position().z, 0.0f);
}

INSTANTIATE_TEST_SUITE_P(Integrators, SolidBodyRotation,
                         ::testing::Values(Integrator::Euler, Integrator::RK2, Integrator::RK4));

TEST(Integration, RK4KeepsTheRadiusWhereEulerSpiralsOut) {
  const float dt = 0.05f;
  const VectorField field = bake(Rotation(1.0f), Box{{-2, -2, -1}, {2, 2, 1}}, {9, 9, 3});
  const auto radiusError = [&](Integrator i) {
    const Particle p = run(field, MotionModel::Tracer, i, dt, 126, {1.0f, 0.0f, 0.0f});
    return std::abs(glm::length(glm::vec2(p.position())) - 1.0f);
  };
  const float euler = radiusError(Integrator::Euler), rk4 = radiusError(Integrator::RK4);
  EXPECT_GT(euler, 0.1f);  // (1 + h^2)^(n/2) - 1 = 0.17
  EXPECT_LT(rk4, 1e-5f);
  EXPECT_LT(rk4 * 1000.0f, euler);
}

TEST(Integration, ForceModelFallsAsUniformAcceleration) {
  // dv/dt = a + g, constant: RK2 and RK4 are exact, Euler lags by a h^2 n / 2.
  const glm::vec3 a(0.0f, 1.0f, 2.0f), g(0.0f, 0.0f, -9.0f), v0(1.0f, 0.0f, 3.0f);
  const VectorField field = bake(Constant(a), Box{{-100, -100, -100}, {100, 100, 100}}, {2, 2, 2});
  const float dt = 0.01f;
  const int n = 100;
  const float t = dt * n;
  const glm::vec3 exact = v0 * t + 0.5f * (a + g) * t * t;
  for (Integrator i : {Integrator::RK2, Integrator::RK4}) {
    const Particle p = run(field, MotionModel::Force, i, dt, n, glm::vec3(0), v0, g);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(p.position()[c], exact[c], 1e-4f);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(p.velocity()[c], (v0 + (a + g) * t)[c], 1e-4f);
  }
  // The thesis's Euler moves with the updated velocity: x_n = v0 t + (a + g) h^2 n (n + 1) / 2.
  const Particle e = run(field, MotionModel::Force, Integrator::Euler, dt, n, glm::vec3(0), v0, g);
  const glm::vec3 eulerExact = v0 * t + (a + g) * (dt * dt * n * (n + 1) / 2.0f);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(e.position()[c], eulerExact[c], 1e-4f);
}

TEST(Integration, DragRelaxesTowardsTheFieldVelocity) {
  // dv/dt = (u - v) / tau: v(t) = u (1 - exp(-t / tau)).
  const glm::vec3 u(2.0f, -1.0f, 0.5f);
  const float tau = 0.1f, dt = 0.01f;
  const int n = 50;
  const VectorField field = bake(Constant(u), Box{{-100, -100, -100}, {100, 100, 100}}, {2, 2, 2});
  const float decay = std::exp(-dt * n / tau);
  const Particle rk4 = run(field, MotionModel::Drag, Integrator::RK4, dt, n, glm::vec3(0),
                           glm::vec3(0), glm::vec3(0), tau);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(rk4.velocity()[c], u[c] * (1 - decay), 1e-5f);
  // Euler: v_n = u (1 - (1 - h / tau)^n).
  const Particle euler = run(field, MotionModel::Drag, Integrator::Euler, dt, n, glm::vec3(0),
                             glm::vec3(0), glm::vec3(0), tau);
  const float eulerDecay = std::pow(1.0f - dt / tau, float(n));
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(euler.velocity()[c], u[c] * (1 - eulerDecay), 1e-5f);
}

TEST(Integration, BoundaryModes) {
  const VectorField field = bake(Constant({1.0f, 0, 0}), Box{{0, 0, 0}, {1, 1, 1}}, {2, 2, 2});
  PhysicsInputs in;
  in.field = &field;
  in.settings.integrator = Integrator::Euler;
  in.settings.groundCollision = false;
  in.dt = 0.3f;
  const Particle start{glm::vec4(0.8f, 0.5f, 0.5f, 10.0f), glm::vec4(0, 0, 0, 10.0f)};

  Particle p = start;
  in.settings.boundary = BoundaryMode::Kill;
  EXPECT_FALSE(advance(p, in));

  p = start;
  in.settings.boundary = BoundaryMode::Clamp;
  EXPECT_TRUE(advance(p, in));
  EXPECT_FLOAT_EQ(p.position().x, 1.0f);

  p = start;
  in.settings.boundary = BoundaryMode::Wrap;
  EXPECT_TRUE(advance(p, in));
  EXPECT_NEAR(p.position().x, 0.1f, 1e-6f);
}

TEST(Integration, LifeRunsOutAfterItsLifetime) {
  PhysicsInputs in;
  in.dt = 0.25f;
  Particle p{glm::vec4(0, 0, 0, 1.0f), glm::vec4(0, 0, 0, 1.0f)};
  EXPECT_TRUE(advance(p, in));   // 0.75 left
  EXPECT_TRUE(advance(p, in));   // 0.5
  EXPECT_TRUE(advance(p, in));   // 0.25
  EXPECT_FALSE(advance(p, in));  // 0
}

TEST(Integration, GroundStopsFallingParticles) {
  const HeightMap ground = HeightMap::flat(0.5f);
  PhysicsInputs in;
  in.terrain = &ground;
  in.settings.motion = MotionModel::Force;
  in.settings.restitution = 0.5f;
  in.settings.integrator = Integrator::Euler;
  in.dt = 0.1f;
  Particle p{glm::vec4(0, 0, 0.6f, 10.0f), glm::vec4(0, 0, -4.0f, 10.0f)};
  EXPECT_TRUE(advance(p, in));
  EXPECT_FLOAT_EQ(p.position().z, 0.5f);
  EXPECT_GT(p.velocity().z, 0.0f);                             // bounced
  EXPECT_NEAR(p.velocity().z, 0.5f * (4.0f + 0.981f), 1e-4f);  // v = -4.981 before the bounce
}

}  // namespace
}  // namespace sandstorm
