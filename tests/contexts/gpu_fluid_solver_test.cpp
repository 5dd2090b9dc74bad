// GpuFluidSolver against FluidSolver (the CPU reference): the same step, pass
// for pass, on a random flow with wind, the rotor, an obstacle and viscosity:
// the velocities agree within float rounding, and the projection leaves the
// same residual.
#include "contexts/solver/gpu_fluid_solver.h"

#include <gtest/gtest.h>

#include "core/sim/counter_rng.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class GpuFluidSolverTest : public GlTest {};

TEST_F(GpuFluidSolverTest, StepsAsTheCpuReferenceDoes) {
  const Box box{{-2, -2, 0}, {2, 2, 2}};
  const glm::ivec3 dims(14, 13, 9);
  VectorField start(box, dims);
  for (std::size_t i = 0; i < start.values().size(); ++i)
    start.values()[i] =
        2.0f * glm::vec3(randomUniform(Seed::from(4), 0, 0, std::uint32_t(i), RngStream::kBirth)) -
        1.0f;
  FluidSettings s;
  s.wind = {1.0f, -0.5f, 0.0f};
  s.viscosity = 0.02f;
  s.vorticity = 0.5f;
  s.iterations = 60;
  FluidForces rotor;
  rotor.rotorCentre = {0.0f, 0.0f, 1.2f};
  rotor.rotorRadius = 0.8f;
  rotor.rotorPressure = 10.0f;
  Obstacle ball;
  ball.position = {1.0f, 0.0f, 0.6f};
  ball.radius = 0.5f;
  FluidSolver cpu(box, dims, &start);
  GpuFluidSolver gpu(box, dims, &start);
  cpu.setSolids(nullptr, {ball});
  gpu.setSolids(nullptr, {ball});
  for (int f = 0; f < 8; ++f) {
    cpu.step(0.03f, s, rotor);
    gpu.step(0.03f, s, rotor);
  }
  const VectorField a = cpu.velocityField(), b = gpu.readVelocityField();
  float worst = 0.0f, fastest = 0.0f;
  for (std::size_t i = 0; i < a.values().size(); ++i) {
    worst = std::max(worst, glm::length(a.values()[i] - b.values()[i]));
    fastest = std::max(fastest, glm::length(a.values()[i]));
  }
  std::printf("GPU against CPU: max |dv| %.3g m/s of %.3g m/s\n", worst, fastest);
  EXPECT_GT(fastest, 0.5f);
  EXPECT_LT(worst, 1e-4f * fastest);
  EXPECT_NEAR(gpu.maxDivergence(), cpu.maxDivergence(), 1e-3);
  // And the step changed the flow (the test would pass on a GPU doing nothing otherwise).
  float moved = 0.0f;
  for (std::size_t i = 0; i < a.values().size(); ++i)
    moved = std::max(moved, glm::length(b.values()[i] - start.values()[i]));
  EXPECT_GT(moved, 0.1f);
}

// The subgrid eddies (no confinement): the same pattern on both, moving with
// each solver's clock; and they do change the field the particles feel.
TEST_F(GpuFluidSolverTest, AddsTheSameSubgridEddiesAsTheCpuReference) {
  const Box box{{-2, -2, 0}, {2, 2, 2}};
  const glm::ivec3 dims(12, 12, 8);
  VectorField start(box, dims);
  for (glm::vec3& v : start.values())
    v = glm::vec3(2.0f, 0.5f, 0.0f);
  FluidSettings s;
  s.wind = {2.0f, 0.5f, 0.0f};
  s.turbulence = 0.4f;
  s.eddySize = 0.7f;
  s.iterations = 60;
  FluidSolver cpu(box, dims, &start), calm(box, dims, &start);
  GpuFluidSolver gpu(box, dims, &start);
  FluidSettings still = s;
  still.turbulence = 0.0f;
  for (int f = 0; f < 10; ++f) {
    cpu.step(0.04f, s);
    gpu.step(0.04f, s);
    calm.step(0.04f, still);
  }
  EXPECT_NEAR(cpu.time(), 0.4, 1e-6);
  const VectorField a = cpu.velocityField(), b = gpu.readVelocityField(), c = calm.velocityField();
  float worst = 0.0f, fastest = 0.0f, churn = 0.0f;
  for (std::size_t i = 0; i < a.values().size(); ++i) {
    worst = std::max(worst, glm::length(a.values()[i] - b.values()[i]));
    fastest = std::max(fastest, glm::length(a.values()[i]));
    churn = std::max(churn, glm::length(a.values()[i] - c.values()[i]));
  }
  std::printf(
      "eddies: GPU against CPU max |dv| %.3g m/s; they changed the field by up to %.3g m/s\n",
      worst, churn);
  EXPECT_LT(worst, 1e-4f * fastest);
  EXPECT_GT(churn, 0.2f);
}

}  // namespace
}  // namespace sandstorm
