// FluidSolver: stable fluids on a MAC grid against what the equations say:
// the projection leaves the flow divergence-free to the stated residual; a
// uniform wind stays uniform; nothing flows through solid cells and the flow
// goes around them; a Taylor-Green vortex decays at the viscous rate.
#include "core/solver/fluid_solver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/sim/counter_rng.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

VectorField randomFlow(const Box& box, glm::ivec3 dims) {
  VectorField f(box, dims);
  for (std::size_t i = 0; i < f.values().size(); ++i)
    f.values()[i] =
        2.0f * glm::vec3(randomUniform(Seed::from(9), 0, 0, std::uint32_t(i), RngStream::kBirth)) -
        1.0f;
  return f;
}

TEST(FluidSolver, TheProjectionLeavesTheFlowDivergenceFree) {
  const Box box{{0, 0, 0}, {3, 3, 2}};
  const glm::ivec3 dims(16, 16, 11);
  const VectorField start = randomFlow(box, dims);
  for (bool closed : {false, true}) {
    FluidSolver solver(box, dims, &start);
    FluidSettings s;
    s.closed = closed;
    s.iterations = 600;
    solver.step(1e-6f, s);  // a step too short to move anything: the projection alone
    // A random flow of 1 m/s over 0.2 m cells diverges by ~10/s; afterwards
    // every fluid cell is within 1e-3 /s (the solver's residual).
    std::printf("projection (%s): max |div| %.3g /s\n", closed ? "closed" : "open",
                solver.maxDivergence());
    EXPECT_LT(solver.maxDivergence(), 1e-3) << (closed ? "closed" : "open");
    // Fewer iterations leave more, still far below the start.
    s.iterations = 40;
    FluidSolver quick(box, dims, &start);
    quick.step(1e-6f, s);
    EXPECT_LT(quick.maxDivergence(), 0.5);
  }
}

TEST(FluidSolver, AUniformWindStaysUniform) {
  const Box box{{-2, -2, 0}, {2, 2, 3}};
  const glm::ivec3 dims(12, 12, 9);
  const glm::vec3 wind(2.0f, -0.5f, 0.0f);
  VectorField start(box, dims, std::vector<glm::vec3>(std::size_t(12 * 12 * 9), wind));
  FluidSolver solver(box, dims, &start);
  FluidSettings s;
  s.wind = wind;
  for (int f = 0; f < 60; ++f)
    solver.step(1.0f / 30.0f, s);
  float worst = 0.0f;
  const VectorField after = solver.velocityField();
  for (const glm::vec3& v : after.values())
    worst = std::max(worst, glm::length(v - wind));
  EXPECT_LT(worst, 1e-4f);
  EXPECT_LT(solver.maxDivergence(), 1e-4);
}

TEST(FluidSolver, NothingFlowsThroughSolidCellsAndTheWindGoesAround) {
  const Box box{{-3, -3, 0}, {3, 3, 3}};
  const glm::ivec3 dims(25, 25, 13);
  const glm::vec3 wind(1.5f, 0.0f, 0.0f);
  VectorField start(box, dims, std::vector<glm::vec3>(std::size_t(25 * 25 * 13), wind));
  FluidSolver solver(box, dims, &start);
  Obstacle block;
  block.shape = ObstacleShape::Box;
  block.position = {0.0f, 0.0f, 1.0f};
  block.size = {1.0f, 2.0f, 2.0f};
  solver.setSolids(nullptr, {block});
  FluidSettings s;
  s.wind = wind;
  s.iterations = 200;
  for (int f = 0; f < 40; ++f)
    solver.step(1.0f / 30.0f, s);
  int solids = 0;
  float sideways = 0.0f;
  const glm::ivec3 n = solver.cells();
  for (int k = 0; k < n.z; ++k)
    for (int j = 0; j < n.y; ++j)
      for (int i = 0; i < n.x; ++i) {
        if (!solver.solid(i, j, k)) continue;
        ++solids;
        // Every face of a solid cell is still (the block does not move).
        EXPECT_EQ(solver.u(i, j, k), 0.0f);
        EXPECT_EQ(solver.u(i + 1, j, k), 0.0f);
        EXPECT_EQ(solver.v(i, j, k), 0.0f);
        EXPECT_EQ(solver.v(i, j + 1, k), 0.0f);
        EXPECT_EQ(solver.w(i, j, k), 0.0f);
        EXPECT_EQ(solver.w(i, j, k + 1), 0.0f);
      }
  EXPECT_GT(solids, 20);
  // In front of the block the wind turns aside (|v| and |w| grow); behind the
  // domain's outflow it keeps the wind's mean flux.
  for (const glm::vec3& p : {glm::vec3(-0.75f, 1.2f, 1.0f), glm::vec3(-0.75f, -1.2f, 1.0f)})
    sideways = std::max(sideways, std::abs(solver.velocityAt(p).y));
  EXPECT_GT(sideways, 0.1f);
  EXPECT_LT(solver.maxDivergence(), 1e-2);
}

// Over terrain, the field's points just under the ground carry the wind's
// horizontal velocity (the free-slip ground's), deeper ones none: dust resting
// on the ground feels the flow over it instead of a blend with still rock.
TEST(FluidSolver, PointsUnderTheGroundCarryTheFlowOverIt) {
  const Box box{{-2, -2, 0}, {2, 2, 2}};
  const glm::ivec3 dims(9, 9, 9);
  const glm::vec3 wind(1.5f, 0.5f, 0.0f);
  VectorField start(box, dims, std::vector<glm::vec3>(std::size_t(9 * 9 * 9), wind));
  FluidSolver solver(box, dims, &start);
  const HeightMap ground = HeightMap::flat(0.8f);  // the cells at z 0, 0.25, 0.5, 0.75 are rock
  solver.setSolids(&ground, {});
  FluidSettings s;
  s.wind = wind;
  for (int f = 0; f < 10; ++f)
    solver.step(1.0f / 30.0f, s);
  const VectorField field = solver.velocityField();
  for (int j = 0; j < 9; ++j)
    for (int i = 0; i < 9; ++i) {
      ASSERT_TRUE(solver.solid(i, j, 3));
      ASSERT_FALSE(solver.solid(i, j, 4));
      const glm::vec3 above = field.at(i, j, 4), under = field.at(i, j, 3);
      EXPECT_EQ(under, glm::vec3(above.x, above.y, 0.0f));
      EXPECT_NEAR(under.x, wind.x, 1e-3f);
      EXPECT_EQ(field.at(i, j, 2), glm::vec3(0.0f));  // deeper: still
    }
  // A particle resting 5 cm on the ground moves with the wind.
  EXPECT_NEAR(field.sample({0.1f, 0.2f, 0.85f}).x, wind.x, 1e-3f);
}

// Subgrid eddies are in the field the particles feel, not in the flow: the
// faces step exactly as without them, and each point's velocity u differs by
// turbulence * |u| times the eddy pattern there, at the solver's time.
TEST(FluidSolver, SubgridEddiesShakeTheFieldNotTheFlow) {
  const Box box{{-2, -2, 0}, {2, 2, 2}};
  const glm::ivec3 dims(10, 10, 6);
  VectorField start(box, dims);
  for (std::size_t i = 0; i < start.values().size(); ++i)
    start.values()[i] = glm::vec3(1.0f + 0.1f * float(i % 7), 0.5f, 0.2f * float(i % 3));
  FluidSettings calm, shaken;
  shaken.turbulence = 0.3f;
  shaken.eddySize = 0.8f;
  FluidSolver a(box, dims, &start), b(box, dims, &start);
  for (int f = 0; f < 6; ++f) {
    a.step(0.05f, calm);
    b.step(0.05f, shaken);
  }
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i <= dims.x; ++i)
        ASSERT_EQ(a.u(i, j, k), b.u(i, j, k));
  const VectorField still = a.velocityField(), felt = b.velocityField();
  float largest = 0.0f;
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) {
        const glm::vec3 u = still.at(i, j, k);
        const glm::vec3 expected =
            u + 0.3f * glm::length(u) *
                    eddyPattern(still.pointPosition(i, j, k), 0.8f, float(b.time()));
        ASSERT_NEAR(glm::length(felt.at(i, j, k) - expected), 0.0f, 1e-5f);
        largest = std::max(largest, glm::length(felt.at(i, j, k) - u));
      }
  EXPECT_GT(largest, 0.1f);
  EXPECT_NEAR(b.time(), 0.3, 1e-6);
}

// Solids are remade only when something moved, and then they follow it.
TEST(FluidSolver, SolidsFollowAMovedObstacle) {
  const Box box{{-2, -2, 0}, {2, 2, 2}};
  FluidSolver solver(box, glm::ivec3(9, 9, 5));
  Obstacle ball;
  ball.position = {-1.0f, 0.0f, 1.0f};
  ball.radius = 0.6f;
  solver.setSolids(nullptr, {ball});
  EXPECT_TRUE(solver.solid(2, 4, 2));  // (-1, 0, 1)
  EXPECT_FALSE(solver.solid(6, 4, 2));
  solver.setSolids(nullptr, {ball});  // the same: unchanged
  EXPECT_TRUE(solver.solid(2, 4, 2));
  ball.position.x = 1.0f;
  solver.setSolids(nullptr, {ball});
  EXPECT_FALSE(solver.solid(2, 4, 2));
  EXPECT_TRUE(solver.solid(6, 4, 2));  // (1, 0, 1)
  FieldPlacement moved;
  moved.offset = {2.0f, 0.0f, 0.0f};  // the field moved 2 m along x: the ball is at its x = -1
  solver.setSolids(nullptr, {ball}, moved);
  EXPECT_TRUE(solver.solid(2, 4, 2));
  EXPECT_FALSE(solver.solid(6, 4, 2));
}

// Taylor-Green: u = U sin(kx) cos(ky), v = -U cos(kx) sin(ky) in a closed box
// of side pi/k (walls on every side, which it slides along). Viscosity nu
// makes its energy decay as exp(-2 nu (kx^2 + ky^2) t); the scheme's own
// dissipation (interpolation in the advection) adds to it: at 32 cells a
// side, under 10 %.
TEST(FluidSolver, ATaylorGreenVortexDecaysAtTheViscousRate) {
  const float L = 1.0f, k = std::numbers::pi_v<float> / L, U = 0.2f, nu = 0.01f;
  const glm::ivec3 dims(33, 33, 2);
  const Box box{{0, 0, 0}, {L, L, L / 32.0f}};
  VectorField start(box, dims);
  for (int j = 0; j < dims.y; ++j)
    for (int i = 0; i < dims.x; ++i)
      for (int z = 0; z < dims.z; ++z) {
        const glm::vec3 p = start.pointPosition(i, j, z);
        start.at(i, j, z) = U * glm::vec3(std::sin(k * p.x) * std::cos(k * p.y),
                                          -std::cos(k * p.x) * std::sin(k * p.y), 0.0f);
      }
  FluidSolver solver(box, dims, &start);
  FluidSettings s;
  s.closed = true;
  s.viscosity = nu;
  s.iterations = 100;
  const double e0 = solver.kineticEnergy();
  const float dt = 0.02f, t = 1.0f;
  for (int f = 0; f < int(t / dt); ++f)
    solver.step(dt, s);
  const double rate = -std::log(solver.kineticEnergy() / e0) / double(t);
  const double viscous = 2.0 * double(nu) * 2.0 * double(k * k);
  std::printf("Taylor-Green: energy decays at %.4f /s, viscous rate %.4f /s (%.3fx)\n", rate,
              viscous, rate / viscous);
  EXPECT_GT(rate, viscous * 0.98);  // never slower than the physics
  EXPECT_LT(rate, viscous * 1.10);  // the scheme's own share under 10 %
}

// Vorticity confinement on a Lamb-Oseen vortex (circulation G, core a):
// w(r) = G / (pi a^2) exp(-r^2 / a^2) along z, so N = grad|w| / |grad|w||
// points to the axis and the force epsilon h (N x w) turns with the swirl,
// of size epsilon h w(r). A short step with it differs from one without by
// that force times dt (the force is divergence-free here: the projection
// keeps it).
TEST(FluidSolver, VorticityConfinementPushesAlongTheSwirl) {
  const float G = 1.0f, a = 0.2f, dt = 1e-3f, epsilon = 1.0f;
  const glm::ivec3 dims(65, 65, 2);
  const Box box{{-1, -1, 0}, {1, 1, 2.0f / 64.0f}};
  VectorField start(box, dims);
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) {
        const glm::vec3 p = start.pointPosition(i, j, k);
        const float r2 = p.x * p.x + p.y * p.y;
        const float speed = r2 > 0.0f ? G / (2.0f * std::numbers::pi_v<float> * r2) *
                                            (1.0f - std::exp(-r2 / (a * a)))
                                      : 0.0f;  // v_theta / r
        start.at(i, j, k) = speed * glm::vec3(-p.y, p.x, 0.0f);
      }
  FluidSettings plain;
  plain.closed = true;
  plain.iterations = 200;
  FluidSettings confined = plain;
  confined.vorticity = epsilon;
  FluidSolver without(box, dims, &start), with(box, dims, &start);
  without.step(dt, plain);
  with.step(dt, confined);
  const float h = 2.0f / 64.0f;
  for (const float r : {0.5f * a, a, 1.5f * a}) {
    for (const glm::vec3 at : {glm::vec3(r, 0.0f, 0.0f), glm::vec3(0.0f, -r, 0.0f)}) {
      const glm::vec3 p = at + glm::vec3(0.0f, 0.0f, 0.5f * box.max.z);
      const glm::vec3 dv = with.velocityAt(p) - without.velocityAt(p);
      const glm::vec3 swirl = glm::normalize(glm::vec3(-at.y, at.x, 0.0f));
      const float expected =
          dt * epsilon * h * G / (std::numbers::pi_v<float> * a * a) * std::exp(-r * r / (a * a));
      EXPECT_NEAR(glm::dot(dv, swirl), expected, 0.15f * expected) << "r " << r;
      EXPECT_LT(glm::length(dv - glm::dot(dv, swirl) * swirl), 0.15f * expected) << "r " << r;
    }
  }
  // Off, the solver is as before: epsilon 0 adds nothing.
  FluidSolver again(box, dims, &start);
  again.step(dt, plain);
  const VectorField x = again.velocityField(), y = without.velocityField();
  EXPECT_TRUE(std::equal(x.values().begin(), x.values().end(), y.values().begin()));
}

// The work is split over threads so that every cell's result is the same
// whatever their number: one thread and three give the same grid, bit for bit.
TEST(FluidSolver, ThreadsDoNotChangeTheFlow) {
  const Box box{{-2, -2, 0}, {2, 2, 2}};
  const glm::ivec3 dims(14, 13, 9);
  const VectorField start = randomFlow(box, dims);
  FluidSettings s;
  s.wind = {1.0f, 0.5f, 0.0f};
  s.viscosity = 0.01f;
  FluidForces rotor;
  rotor.rotorCentre = {0.0f, 0.0f, 1.2f};
  rotor.rotorRadius = 0.8f;
  rotor.rotorPressure = 10.0f;
  Obstacle ball;
  ball.position = {1.0f, 0.0f, 0.6f};
  ball.radius = 0.5f;
  FluidSolver one(box, dims, &start, 1), three(box, dims, &start, 3);
  one.setSolids(nullptr, {ball});
  three.setSolids(nullptr, {ball});
  for (int f = 0; f < 10; ++f) {
    one.step(0.03f, s, rotor);
    three.step(0.03f, s, rotor);
  }
  const VectorField a = one.velocityField(), b = three.velocityField();
  ASSERT_EQ(a.values().size(), b.values().size());
  for (std::size_t i = 0; i < a.values().size(); ++i)
    ASSERT_EQ(a.values()[i], b.values()[i]) << i;
}

TEST(FluidSolver, RefusesGridsItCannotSolveOn) {
  EXPECT_THROW(FluidSolver(Box{{0, 0, 0}, {1, 1, 1}}, glm::ivec3(1, 4, 4)), Error);
  EXPECT_THROW(FluidSolver(Box{{0, 0, 0}, {0, 1, 1}}, glm::ivec3(4, 4, 4)), Error);
}

}  // namespace
}  // namespace sandstorm
