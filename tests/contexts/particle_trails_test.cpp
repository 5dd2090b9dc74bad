// Trails follow their particles through births, deaths and either backend's
// compaction (the compute update's scan, the transform feedback's dropped
// primitives): in a uniform wind every trail is its particle's last
// positions, one step of wind apart, on its own line.
#include <gtest/gtest.h>

#include <memory>

#include "contexts/particles/particle_compute_update.h"
#include "contexts/particles/particle_geo_update.h"
#include "contexts/particles/particle_trails.h"
#include "core/field/analytic_field.h"
#include "core/sim/main_context.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class ParticleTrailsTest : public GlTest {};

struct Wind final : AnalyticField {
  glm::vec3 evaluate(const glm::vec3&) const override { return {1.0f, 0.0f, 0.0f}; }
};

constexpr float kDt = 0.25f;

ParticleState windState(int trailLength) {
  ParticleState s;
  s.sim.groundCollision = false;
  s.render.trailLength = trailLength;
  Emitter& e = s.emitters[0];
  e.shape = EmitterShape::Box;  // a line across the wind: every particle on a line of its own
  e.position = {0.0f, 0.0f, 2.0f};
  e.width = 0.0f;
  e.depth = 4.0f;
  e.height = 0.0f;
  e.rate = 40.0f;  // 10 a frame
  e.lifetime = 2.0f;
  e.lifetimeVariance = 1.5f;  // deaths out of birth order: the compaction moves records
  e.velocity = {1.0f, 0.0f, 0.0f};
  return s;
}

// Runs the backend `frames` frames; returns its particles and their trails.
struct Run {
  std::vector<Particle> particles;
  std::vector<std::vector<glm::vec3>> trails;
};

void checkTrails(const Run& run, int length) {
  ASSERT_EQ(run.particles.size(), run.trails.size());
  ASSERT_GT(run.particles.size(), 20u);
  int full = 0;
  for (std::size_t i = 0; i < run.particles.size(); ++i) {
    const glm::vec3 p = run.particles[i].position();
    const std::vector<glm::vec3>& trail = run.trails[i];
    ASSERT_FALSE(trail.empty()) << "record " << i;
    // Frames lived: x moves by 1 m/s x 0.25 s a frame from x = 0.
    const int lived = int(std::lround(p.x / kDt));
    EXPECT_EQ(int(trail.size()), std::min(lived + 1, length)) << "record " << i << " at x " << p.x;
    for (std::size_t j = 0; j < trail.size(); ++j) {
      EXPECT_NEAR(trail[j].x, p.x - kDt * float(j), 1e-4f) << "record " << i << ", point " << j;
      EXPECT_EQ(trail[j].y, p.y) << "record " << i << " has another particle's trail";
      EXPECT_EQ(trail[j].z, p.z);
    }
    full += int(trail.size()) == length ? 1 : 0;
  }
  EXPECT_GT(full, 10) << "some trails should be full";
}

std::vector<std::vector<glm::vec3>> trailsOf(const ParticleBackend& gpu) {
  const ParticleBackend::Records r = gpu.records();
  return ParticleTrails::read(r.trails, r.trailLength, r.trailHead, gpu.liveCount());
}

TEST_F(ParticleTrailsTest, EachTrailIsItsParticlesLastPositionsThroughBirthsAndDeaths) {
  auto field =
      std::make_shared<VectorField>(bake(Wind(), Box{{-50, -50, 0}, {50, 50, 10}}, {2, 2, 2}));
  for (const char* backend : {"compute", "tf-gs"}) {
    SCOPED_TRACE(backend);
    std::unique_ptr<ParticleBackend> gpu;
    if (std::string(backend) == "compute")
      gpu = std::make_unique<ParticleComputeUpdate>(4096);
    else
      gpu = std::make_unique<ParticleGeoUpdate>(4096);
    gpu->setField(field, {});
    MainContext::Options options;
    options.fixedDt = kDt;
    options.seed = 5;
    MainContext main(windState(5), FieldUpdate{.field = field}, options);
    ParticleState state = main.initialState();
    auto step = [&] {
      const FramePacket packet = main.next();
      for (const StateChange& c : packet.changes)
        applyChange(state, c);
      gpu->step(packet.step(), state);
    };
    for (int f = 0; f < 24; ++f)
      step();
    checkTrails({gpu->readBack(), trailsOf(*gpu)}, 5);

    // A new length starts every trail afresh.
    main.set("render.trail_length", 8);
    for (int f = 0; f < 3; ++f)
      step();
    const auto trails = trailsOf(*gpu);
    ASSERT_FALSE(trails.empty());
    for (const auto& t : trails)
      EXPECT_LE(t.size(), 3u);
    // Off: no trails.
    main.set("render.trail_length", 0);
    step();
    EXPECT_TRUE(trailsOf(*gpu).empty());
  }
}

}  // namespace
}  // namespace sandstorm
