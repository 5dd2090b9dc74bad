// The GPU's streaklines against the CPU twin, and in a wind against the
// analytic line: points one step of wind apart, downwind of the emitter.
#include "contexts/scene/streakline_renderer.h"

#include <gtest/gtest.h>

#include "core/field/analytic_field.h"
#include "core/field/vortex_field.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class StreaklineGpuTest : public GlTest {};

struct Wind final : AnalyticField {
  glm::vec3 evaluate(const glm::vec3&) const override { return {2.0f, 0.0f, 0.0f}; }
};

ParticleState pointEmitters(std::vector<glm::vec3> where) {
  ParticleState s;
  s.emitters.clear();
  for (const glm::vec3& p : where) {
    Emitter e;
    e.shape = EmitterShape::Point;
    e.position = p;
    s.emitters.push_back(e);
  }
  s.render.streaklines = true;
  s.render.streakLength = 10;
  s.sim.integrator = Integrator::RK4;
  return s;
}

TEST_F(StreaklineGpuTest, InAWindTheyAreStraightLinesDownwindOfTheEmitter) {
  auto wind =
      std::make_shared<VectorField>(bake(Wind(), Box{{-50, -50, 0}, {50, 50, 10}}, {2, 2, 2}));
  ParticleState state = pointEmitters({{0, 0, 1}, {0, 3, 2}});
  const float dt = 0.1f;
  SceneField field;
  StreaklineRenderer gpu(field);
  for (int f = 0; f < 6; ++f) {
    field.set(state, FieldUpdate{.field = wind}, 0.0f, dt);
    gpu.update(state, dt, false);
  }
  const std::vector<StreakPoint> line = gpu.readBack(1);
  ASSERT_EQ(line.size(), 6u);  // six frames, six releases, none older
  for (std::size_t j = 0; j < line.size(); ++j) {
    EXPECT_NEAR(line[j].position.x, 0.2f * float(j), 1e-5f) << j;  // 2 m/s x 0.1 s a frame
    EXPECT_EQ(line[j].position.y, 3.0f);
    EXPECT_EQ(line[j].position.z, 2.0f);
  }
  EXPECT_TRUE(gpu.readBack(2).empty());  // no third emitter
}

TEST_F(StreaklineGpuTest, TheGpuMovesThePointsAsTheCpuTwinDoes) {
  auto tornado = std::make_shared<VectorField>(
      bake(VortexField(VortexParams{}), Box{{-6, -6, 0}, {6, 6, 10}}, {16, 16, 12}));
  ParticleState state = pointEmitters({{1, 0, 1}, {-2, 1, 0.5f}, {0, -3, 2}});
  state.emitters[2].enabled = false;  // releases nothing
  state.render.streakLength = 40;
  const float dt = 1.0f / 30.0f;
  SceneField field;
  StreaklineRenderer gpu(field);
  StreaklineReference cpu;
  PhysicsInputs in;
  in.field = tornado.get();
  in.settings = state.sim;
  in.dt = dt;
  for (int f = 0; f < 60; ++f) {
    field.set(state, FieldUpdate{.field = tornado}, 0.0f, dt);
    gpu.update(state, dt, false);
    cpu.step(state, in);
  }
  float worst = 0.0f;
  for (int e = 0; e < 3; ++e) {
    const auto a = gpu.readBack(e), b = cpu.line(e);
    ASSERT_EQ(a.size(), b.size()) << "emitter " << e;
    for (std::size_t j = 0; j < a.size(); ++j)
      worst = std::max(worst, glm::length(a[j].position - b[j].position));
  }
  EXPECT_TRUE(gpu.readBack(2).empty());
  EXPECT_EQ(gpu.readBack(0).size(), 40u);
  EXPECT_LT(worst, 1e-4f);
}

}  // namespace
}  // namespace sandstorm
