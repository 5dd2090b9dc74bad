// ParticleMeasure against the CPU: the colour quantity's least and greatest
// value over the live particles and the count near the probe, from the same
// particles read back.
#include "contexts/particles/particle_measure.h"

#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include "contexts/particles/particle_compute_update.h"
#include "contexts/render/frame_blocks.h"
#include "core/field/vortex_field.h"
#include "core/sim/main_context.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class ParticleMeasureTest : public GlTest {};

TEST_F(ParticleMeasureTest, MeasuresWhatTheCpuFindsInTheSameParticles) {
  auto field = std::make_shared<VectorField>(
      bake(VortexField(VortexParams{}), Box{{-6, -6, 0}, {6, 6, 10}}, {16, 16, 12}));
  ParticleState state;
  state.render.colorBy = ColorQuantity::Speed;
  Emitter& e = state.emitters[0];
  e.shape = EmitterShape::Sphere;
  e.position = {0.0f, 0.0f, 3.0f};
  e.radius = 3.0f;
  e.rate = 20000.0f;
  e.lifetime = 1.0f;
  ParticleComputeUpdate gpu(8192);
  gpu.setField(field, {});
  MainContext::Options options;
  options.fixedDt = 1.0f / 30.0f;
  MainContext main(state, FieldUpdate{.field = field}, options);
  for (int f = 0; f < 12; ++f)
    gpu.step(main.next().step(), state);

  // The render block says which quantity (speed here, then velocity z).
  gl::Buffer block = gl::createBuffer();
  glNamedBufferStorage(block.id(), sizeof(RenderBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  const glm::vec3 probe(1.0f, 0.5f, 3.0f);
  const float radius = 1.2f;
  for (const ColorQuantity q : {ColorQuantity::Speed, ColorQuantity::VelocityZ}) {
    state.render.colorBy = q;
    const RenderBlock rb =
        makeRenderBlock(state, nullptr, 0.0f, ColorMap(state.render.colorMap).gpuTable());
    glNamedBufferSubData(block.id(), 0, sizeof rb, &rb);
    glBindBufferBase(GL_UNIFORM_BUFFER, 2, block.id());
    ParticleMeasure measure;
    measure.measure(7, gpu.records(), gpu.capacity(), glm::vec4(probe, radius));
    glFinish();
    const std::optional<ParticleMeasurement> m = measure.latest();
    ASSERT_TRUE(m);
    const std::vector<Particle> particles = gpu.readBack();
    ASSERT_GT(particles.size(), 1000u);
    float least = 1e30f, greatest = -1e30f;
    std::uint32_t near = 0;
    for (const Particle& p : particles) {
      const float v = colorValue(p, q);
      least = std::min(least, v);
      greatest = std::max(greatest, v);
      near += glm::length(p.position() - probe) <= radius ? 1u : 0u;
    }
    EXPECT_EQ(m->frame, 7u);
    EXPECT_EQ(m->live, particles.size());
    EXPECT_FLOAT_EQ(m->least, least);
    EXPECT_FLOAT_EQ(m->greatest, greatest);
    EXPECT_EQ(m->nearProbe, near);
    EXPECT_GT(near, 10u);
  }
}

}  // namespace
}  // namespace sandstorm
