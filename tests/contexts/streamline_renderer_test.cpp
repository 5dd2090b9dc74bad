// The GPU's streamlines against the CPU twin (core/flow's traceStreamlines),
// for every streamlines.integrator: same lines, nearly the same lengths, on
// the same curves to a tenth of a millimetre.
#include "contexts/scene/streamline_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "core/field/analytic_field.h"
#include "core/field/vortex_field.h"
#include "tests/contexts/gl_test.h"
#include "tests/core/sparse_grid_builder.h"

namespace sandstorm {
namespace {

class StreamlineGpuTest : public GlTest {};

struct Breeze final : AnalyticField {  // a different field for the time-varying blend
  glm::vec3 evaluate(const glm::vec3& p) const override { return {1.0f, 0.3f * p.z, 0.2f}; }
};

// The distance from x to the polyline (its nearest segment).
float toPolyline(const glm::vec3& x, const std::vector<StreamlinePoint>& line) {
  float best = glm::length(x - line.front().position);
  for (std::size_t i = 1; i < line.size(); ++i) {
    const glm::vec3 a = line[i - 1].position, d = line[i].position - a;
    const float len2 = glm::dot(d, d);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(x - a, d) / len2, 0.0f, 1.0f) : 0.0f;
    best = std::min(best, glm::length(x - (a + t * d)));
  }
  return best;
}

// The same lines: as many, of nearly as many points, every point of each on
// the other's polyline. Point for point would ask too much: float rounding
// may end a line a step earlier or later at the field's edge, and may flip an
// adaptive step's acceptance, after which the points fall elsewhere on the
// same curve.
void expectSame(const std::vector<Streamline>& gpu, const std::vector<Streamline>& cpu,
                const std::string& what) {
  ASSERT_EQ(gpu.size(), cpu.size()) << what;
  float worst = 0.0f;
  std::size_t points = 0;
  for (std::size_t l = 0; l < cpu.size(); ++l) {
    const double n = double(cpu[l].points.size());
    EXPECT_NEAR(double(gpu[l].points.size()), n, 2.0 + 0.02 * n) << what << " line " << l;
    EXPECT_EQ(gpu[l].points[std::size_t(gpu[l].seedIndex)].position,
              cpu[l].points[std::size_t(cpu[l].seedIndex)].position)
        << what << " line " << l;
    for (const StreamlinePoint& p : gpu[l].points)
      worst = std::max(worst, toPolyline(p.position, cpu[l].points));
    for (const StreamlinePoint& p : cpu[l].points)
      worst = std::max(worst, toPolyline(p.position, gpu[l].points));
    points += gpu[l].points.size();
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
  state.sim.integrator = Integrator::Euler;  // the particles': the streamlines have their own
  in.settings = state.sim;
  for (const StreamIntegrator integrator : {StreamIntegrator::RK45, StreamIntegrator::RK4,
                                            StreamIntegrator::RK2, StreamIntegrator::Euler}) {
    state.streamlines.integrator = integrator;
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
  state.streamlines.integrator = StreamIntegrator::RK45;
  in.nextField = next.get();
  in.blend = 0.5f;
  SceneField sceneField;
  sceneField.set(state, update, 0.5f);
  StreamlineRenderer renderer(sceneField);
  renderer.update(state, std::make_shared<const FieldUpdate>(update), 0.5f);
  expectSame(renderer.readBack(), traceStreamlines(state.streamlines, in), "blended");
}

// A sparse grid (NanoVDB): the tornado's voxels within 4.5 m of its axis,
// traced on the GPU through the sparse grid (FIELD_SPARSE) as on the CPU, not
// through the coarse overview the update carries as its `field`.
TEST_F(StreamlineGpuTest, TheGpuTracesTheCpusStreamlinesThroughASparseGrid) {
  const VortexField vortex{VortexParams{}};
  const glm::vec3 origin(-6.0f, -6.0f, 0.0f);
  auto sparse = std::make_shared<const SparseField>(
      test::buildSparseGrid(
          [&](const auto& set) {
            for (int k = 0; k <= 40; ++k)
              for (int j = 0; j <= 48; ++j)
                for (int i = 0; i <= 48; ++i) {
                  const glm::vec3 p = origin + 0.25f * glm::vec3(i, j, k);
                  if (glm::length(glm::vec2(p)) < 4.5f) set({i, j, k}, vortex.evaluate(p));
                }
          },
          0.25, glm::dvec3(origin)),
      "tornado.nvdb");
  auto overview = std::make_shared<const VectorField>(sparse->overview(3));
  ParticleState state;
  state.streamlines.enabled = true;
  state.streamlines.shape = RakeShape::Line;
  state.streamlines.from = {-3.0f, 0.5f, 1.0f};
  state.streamlines.to = {3.0f, 0.5f, 1.0f};
  state.streamlines.seeds = 6;
  state.streamlines.step = 0.05f;
  state.streamlines.length = 15.0f;
  state.streamlines.integrator = StreamIntegrator::RK4;
  const FieldUpdate update{.field = overview, .sparse = sparse};
  PhysicsInputs in;
  in.field = overview.get();
  in.sparse = sparse.get();
  in.settings = state.sim;
  SceneField sceneField;
  sceneField.set(state, update, 0.0f);
  EXPECT_TRUE(sceneField.sparse());
  StreamlineRenderer renderer(sceneField);
  renderer.update(state, std::make_shared<const FieldUpdate>(update), 0.0f);
  const std::vector<Streamline> gpu = renderer.readBack();
  expectSame(gpu, traceStreamlines(state.streamlines, in), "sparse tornado");
  // Through the overview alone the lines would differ.
  in.sparse = nullptr;
  const std::vector<Streamline> coarse = traceStreamlines(state.streamlines, in);
  float apart = 0.0f;
  for (std::size_t l = 0; l < std::min(gpu.size(), coarse.size()); ++l)
    apart = std::max(apart,
                     glm::length(gpu[l].points.back().position - coarse[l].points.back().position));
  EXPECT_GT(apart, 0.1f);
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
