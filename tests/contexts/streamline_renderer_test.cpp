// The GPU's streamlines against the CPU twin (core/flow's traceStreamlines):
// same lines, same lengths, the same points to float rounding.
#include "contexts/scene/streamline_renderer.h"

#include <gtest/gtest.h>

#include "core/field/analytic_field.h"
#include "core/field/vortex_field.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class StreamlineGpuTest : public GlTest {};

struct Breeze final : AnalyticField {  // a different field for the time-varying blend
  glm::vec3 evaluate(const glm::vec3& p) const override { return {1.0f, 0.3f * p.z, 0.2f}; }
};

void expectSame(const std::vector<Streamline>& gpu, const std::vector<Streamline>& cpu,
                const std::string& what) {
  ASSERT_EQ(gpu.size(), cpu.size()) << what;
  float worst = 0.0f;
  std::size_t points = 0;
  for (std::size_t l = 0; l < cpu.size(); ++l) {
    // Float rounding may end a line a step earlier or later at the field's edge.
    EXPECT_NEAR(double(gpu[l].points.size()), double(cpu[l].points.size()), 2.0)
        << what << " line " << l;
    EXPECT_NEAR(gpu[l].seedIndex, cpu[l].seedIndex, 1) << what << " line " << l;
    const int offset = cpu[l].seedIndex - gpu[l].seedIndex;
    for (std::size_t i = 0; i < gpu[l].points.size(); ++i) {
      const int j = int(i) + offset;
      if (j < 0 || j >= int(cpu[l].points.size())) continue;
      worst = std::max(
          worst, glm::length(gpu[l].points[i].position - cpu[l].points[std::size_t(j)].position));
      ++points;
    }
  }
  std::printf("[ measured ] %s: %zu points, GPU vs CPU max %.3g m\n", what.c_str(), points,
              double(worst));
  EXPECT_GT(points, 100u) << what;
  EXPECT_LT(worst, 1e-4f) << what;
}

TEST_F(StreamlineGpuTest, TheGpuTracesTheCpusStreamlines) {
  auto tornado = std::make_shared<VectorField>(
      bake(VortexField(VortexParams{}), Box{{-6, -6, 0}, {6, 6, 10}}, {25, 25, 21}));
  ParticleState state;
  state.streamlines.enabled = true;
  state.streamlines.shape = RakeShape::Plane;
  state.streamlines.from = {-3.0f, 0.5f, 1.0f};
  state.streamlines.to = {3.0f, 0.5f, 1.0f};
  state.streamlines.across = {-3.0f, 0.5f, 6.0f};
  state.streamlines.seeds = 4;
  state.streamlines.step = 0.05f;
  state.streamlines.length = 15.0f;
  FieldUpdate update{.field = tornado, .placement = {.offset = {0.5f, -0.2f, 0.0f}, .scale = 0.8f}};
  PhysicsInputs in;
  in.field = tornado.get();
  in.placement = update.placement;
  for (const Integrator integrator : {Integrator::RK4, Integrator::RK2, Integrator::Euler}) {
    state.sim.integrator = integrator;
    in.settings = state.sim;
    SceneField sceneField;
    sceneField.set(state, update, 0.0f);
    StreamlineRenderer renderer(sceneField);
    renderer.update(state, std::make_shared<const FieldUpdate>(update), 0.0f);
    expectSame(renderer.readBack(), traceStreamlines(state.streamlines, in),
               "tornado, integrator " + std::to_string(int(integrator)));
  }
  // A time-varying field halfway to its next frame.
  auto next = std::make_shared<VectorField>(bake(Breeze(), tornado->bounds(), tornado->dims()));
  update.next = next;
  state.sim.integrator = Integrator::RK4;
  in.settings = state.sim;
  in.nextField = next.get();
  in.blend = 0.5f;
  SceneField sceneField;
  sceneField.set(state, update, 0.5f);
  StreamlineRenderer renderer(sceneField);
  renderer.update(state, std::make_shared<const FieldUpdate>(update), 0.5f);
  expectSame(renderer.readBack(), traceStreamlines(state.streamlines, in), "blended");
}

TEST_F(StreamlineGpuTest, NothingIsTracedWhileStreamlinesAreOff) {
  auto tornado = std::make_shared<VectorField>(
      bake(VortexField(VortexParams{}), Box{{-6, -6, 0}, {6, 6, 10}}, {9, 9, 9}));
  ParticleState state;  // streamlines.enabled is false by default
  SceneField sceneField;
  StreamlineRenderer renderer(sceneField);
  renderer.update(state, std::make_shared<const FieldUpdate>(FieldUpdate{.field = tornado}), 0.0f);
  EXPECT_TRUE(renderer.readBack().empty());
}

}  // namespace
}  // namespace sandstorm
