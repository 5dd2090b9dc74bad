#include "core/sim/reference_simulator.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "core/sim/emission.h"

namespace sandstorm {
namespace {

SimStep stepFor(const ParticleState& s, std::uint32_t frame, float dt) {
  return SimStep{frame, dt, Seed::from(7), emissionCounts(s, dt, Seed::from(7), frame)};
}

TEST(ReferenceSimulator, ParticlesLiveExactlyTheirLifetime) {
  ParticleState s;
  s.emitters[0].rate = 100.0f;  // dt 0.1: exactly 10 a frame (mean 10, no variance)
  s.emitters[0].lifetime = 0.5f;
  ReferenceSimulator sim(1000);
  std::vector<std::size_t> counts;
  for (std::uint32_t f = 0; f < 12; ++f) {
    sim.step(stepFor(s, f, 0.125f), s);
    counts.push_back(sim.particles().size());
  }
  // 12.5/frame on average; a particle born with life 0.5 survives 3 updates (0.375, 0.25, 0.125)
  // and dies in the 4th, so the steady state holds 4 frames of births: about 50.
  EXPECT_NEAR(double(counts.back()), 50.0, 6.0);
  for (const Particle& p : sim.particles()) {
    EXPECT_GT(p.life(), 0.0f);
    EXPECT_LE(p.life(), 0.5f);
  }
}

TEST(ReferenceSimulator, NewbornComeFirstAndSurvivorsKeepTheirOrder) {
  ParticleState s;
  s.emitters[0].rate = 80.0f;
  s.emitters[0].lifetime = 10.0f;
  ReferenceSimulator sim(1000);
  sim.step(stepFor(s, 0, 0.1f), s);
  const std::vector<Particle> first(sim.particles().begin(), sim.particles().end());
  const SimStep step = stepFor(s, 1, 0.1f);
  sim.step(step, s);
  const std::size_t born = step.emission[0];
  ASSERT_EQ(sim.particles().size(), born + first.size());
  for (std::size_t i = 0; i < born; ++i)
    EXPECT_FLOAT_EQ(sim.particles()[i].life(), 10.0f);
  for (std::size_t i = 0; i < first.size(); ++i)
    EXPECT_FLOAT_EQ(sim.particles()[born + i].life(), first[i].life() - 0.1f);
}

// Adopting another simulator's particles continues from them: two simulators
// that parted (one stepped once more) agree again after the one adopts.
TEST(ReferenceSimulator, AdoptedParticlesAreWhereTheNextUpdateStarts) {
  ParticleState s;
  s.emitters[0].rate = 80.0f;
  s.emitters[0].lifetime = 10.0f;
  s.emitters[0].velocity = {0.5f, 0.0f, 0.0f};
  ReferenceSimulator a(1000), b(1000);
  a.step(stepFor(s, 0, 0.1f), s);
  b.step(stepFor(s, 0, 0.1f), s);
  std::vector<Particle> moved(a.particles().begin(), a.particles().end());
  for (Particle& p : moved)
    p.positionLife.x += 1.0f;
  b.adopt(moved);
  EXPECT_EQ(b.particles()[0].positionLife.x, moved[0].positionLife.x);
  a.adopt(moved);
  a.step(stepFor(s, 1, 0.1f), s);
  b.step(stepFor(s, 1, 0.1f), s);
  ASSERT_EQ(a.particles().size(), b.particles().size());
  for (std::size_t i = 0; i < a.particles().size(); ++i)
    EXPECT_EQ(a.particles()[i].positionLife, b.particles()[i].positionLife);
  moved.pop_back();
  EXPECT_THROW(b.adopt(moved), std::invalid_argument);
}

TEST(ReferenceSimulator, MaximumIsASoftLimitAndCapacityAHardOne) {
  ParticleState s;
  s.emitters[0].rate = 1e5f;
  s.emitters[0].lifetime = 100.0f;
  s.sim.maximum = 700;
  ReferenceSimulator sim(1000);
  for (std::uint32_t f = 0; f < 30; ++f) {
    sim.step(stepFor(s, f, 0.01f), s);  // 1000 wanted per frame
    ASSERT_LE(sim.particles().size(), 700u);
  }
  EXPECT_GE(sim.particles().size(), 690u);  // settles close below Maximum
  s.sim.maximum = 5000;
  for (std::uint32_t f = 30; f < 60; ++f) {
    sim.step(stepFor(s, f, 0.01f), s);
    ASSERT_LE(sim.particles().size(), 1000u);
  }
}

TEST(ReferenceSimulator, SameSeedSameParticlesOtherSeedOthers) {
  ParticleState s;
  s.emitters[0].rate = 500.0f;
  s.emitters[0].spread = 1.0f;
  ReferenceSimulator a(1000), b(1000), c(1000);
  for (std::uint32_t f = 0; f < 5; ++f) {
    a.step(stepFor(s, f, 0.05f), s);
    b.step(stepFor(s, f, 0.05f), s);
    SimStep other = stepFor(s, f, 0.05f);
    other.seed = Seed::from(8);
    c.step(other, s);
  }
  ASSERT_EQ(a.particles().size(), b.particles().size());
  for (std::size_t i = 0; i < a.particles().size(); ++i)
    EXPECT_EQ(a.particles()[i].positionLife, b.particles()[i].positionLife);
  EXPECT_NE(a.particles()[0].positionLife, c.particles()[0].positionLife);
}

TEST(ReferenceSimulator, BirthFillsTheEmitterShape) {
  ParticleState s;
  Emitter& e = s.emitters[0];
  e.position = {1, 2, 3};
  e.rate = 2000.0f;
  e.lifetime = 10.0f;
  struct Case {
    EmitterShape shape;
    std::function<bool(glm::vec3)> inside;
  };
  e.width = 2.0f;
  e.depth = 1.0f;
  e.radius = 0.5f;
  for (const Case& c :
       {Case{EmitterShape::Box,
             [](glm::vec3 d) { return std::abs(d.x) <= 1 && std::abs(d.y) <= 0.5f && d.z == 0; }},
        Case{EmitterShape::Sphere, [](glm::vec3 d) { return glm::length(d) <= 0.5f + 1e-6f; }},
        Case{EmitterShape::Disc,
             [](glm::vec3 d) { return glm::length(d) <= 0.5f + 1e-6f && d.z == 0; }},
        Case{EmitterShape::Point, [](glm::vec3 d) { return d == glm::vec3(0); }}}) {
    e.shape = c.shape;
    ReferenceSimulator sim(10000);
    sim.step(stepFor(s, 0, 0.5f), s);
    ASSERT_GT(sim.particles().size(), 900u);
    glm::vec3 mean(0);
    for (const Particle& p : sim.particles()) {
      const glm::vec3 d = p.position() - e.position;
      ASSERT_TRUE(c.inside(d)) << int(c.shape) << ": " << d.x << " " << d.y << " " << d.z;
      mean += d;
    }
    mean /= float(sim.particles().size());
    EXPECT_LT(glm::length(mean), 0.05f) << "shape " << int(c.shape) << " is centred";
  }
}

}  // namespace
}  // namespace sandstorm
