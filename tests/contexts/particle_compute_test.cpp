// The compute backend beyond the shared backend tests: its scan gives the CPU
// reference's particles whatever the workgroups' schedule (a tile that stops
// waiting for a slow predecessor counts that tile itself), and its indirect
// draw shows the same image as the transform-feedback path.
#include <gtest/gtest.h>

#include <cstdlib>

#include "contexts/particles/particle_compute_update.h"
#include "contexts/render/wall_renderer.h"
#include "core/field/vortex_field.h"
#include "core/sim/main_context.h"
#include "core/sim/reference_simulator.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class ParticleComputeTest : public GlTest {};

ParticleState busyState() {
  ParticleState s;
  s.sim.maximum = 20000;
  s.sim.integrator = Integrator::RK4;
  Emitter& e = s.emitters[0];
  e.shape = EmitterShape::Sphere;
  e.position = {0.0f, 0.0f, 2.0f};
  e.radius = 2.0f;
  e.rate = 30000.0f;
  e.lifetime = 0.6f;
  e.lifetimeVariance = 0.4f;
  e.spread = 1.0f;
  return s;
}

std::shared_ptr<const VectorField> vortex() {
  VortexParams vp;
  vp.range = 3.0f;
  return std::make_shared<VectorField>(
      bake(VortexField(vp), Box{{-3, -3, 0}, {3, 3, 4}}, {16, 16, 12}));
}

// Runs `frames` updates of the compute backend with the given look-back spin
// limit against the CPU; returns the frames whose records all matched bit for bit.
int matchingFrames(std::uint32_t spin, int frames) {
  ParticleComputeUpdate gpu(16384, GpuTuning{.scanSpin = spin});
  ReferenceSimulator cpu(16384);
  MainContext::Options options;
  options.fixedDt = 1.0f / 60.0f;
  options.seed = 77;
  MainContext main(busyState(), FieldUpdate{.field = vortex()}, options);
  ParticleState state = main.initialState();
  int matching = 0;
  for (int f = 0; f < frames; ++f) {
    const FramePacket packet = main.next();
    for (const StateChange& c : packet.changes)
      applyChange(state, c);
    if (packet.fieldUpdate) {
      gpu.setField(packet.fieldUpdate->field, {});
      cpu.setField(packet.fieldUpdate->field, {});
    }
    gpu.step(packet.step(), state);
    cpu.step(packet.step(), state);
    const std::vector<Particle> g = gpu.readBack();
    const auto c = cpu.particles();
    if (g.size() != c.size()) break;
    bool same = true;
    for (std::size_t i = 0; i < g.size() && same; ++i)
      same = g[i].positionLife == c[i].positionLife && g[i].velocityKind == c[i].velocityKind;
    if (!same) break;
    ++matching;
  }
  return matching;
}

TEST_F(ParticleComputeTest, TheScanMatchesTheReferenceWhetherTilesWaitOrCountForThemselves) {
  // 0: every tile counts its predecessors itself; larger: tiles wait for one
  // another more, as on a GPU (llvmpipe caps a shader's loop iterations in all,
  // so its waits stay short).
  for (const std::uint32_t spin : {0u, 3u, 200u}) {
    SCOPED_TRACE(spin);
    EXPECT_EQ(matchingFrames(spin, 40), 40);
  }
}

TEST_F(ParticleComputeTest, IndirectDrawShowsTheSameImageAsTransformFeedback) {
  ParticleState state = busyState();
  state.render.size = 0.3f;
  auto image = [&](const std::string& backend) {
    MainContext::Options options;
    options.fixedDt = 1.0f / 30.0f;
    MainContext main(state, FieldUpdate{.field = vortex()}, options);
    WallSpec wall;
    wall.name = "test";
    wall.camera = CameraSpec{{0.0f, -9.0f, 2.0f}, {0.0f, 0.0f, 2.0f}, 50.0f};
    wall.offscreenSize = {96, 64};
    WallRenderer renderer(
        WallRendererSetup{.wall = wall,
                          .initial = state,
                          .terrain = std::make_shared<HeightMap>(HeightMap::flat(0.0f)),
                          .capacity = 16384,
                          .backend = backend,
                          .nearPlane = 0.1f,
                          .farPlane = 100.0f});
    for (int f = 0; f < 12; ++f)
      renderer.frame(main.next(), {0, 0});
    return renderer.capture();
  };
  const Image tf = image("tf-gs"), compute = image("compute");
  ASSERT_EQ(tf.rgba.size(), compute.rgba.size());
  EXPECT_TRUE(tf.rgba == compute.rgba);
  // And the image is not empty: particles cover part of it.
  const Image none = [&] {
    state.emitters[0].rate = 0.0f;
    return image("compute");
  }();
  EXPECT_FALSE(none.rgba == compute.rgba);
}

}  // namespace
}  // namespace sandstorm
