// The downdraft demo (thesis chapter 6), end to end on the GPU: the rotor wash
// raises dust from the terrain under the helicopter, and the throttle and
// altitude controls drive how much; in the live flow (the demo's default) the
// wall jet carries the dust out along the ground and it rises farther out.
#include <gtest/gtest.h>

#include <algorithm>

#include "app/fluid_driver.h"
#include "app/helicopter_controller.h"
#include "app/scene_setup.h"
#include "contexts/particles/particle_system.h"
#include "core/config/app_config.h"
#include "core/sim/main_context.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class DowndraftTest : public GlTest {};

struct Dust {
  std::size_t count = 0;
  float airborne = 0.0f;  // share more than 1.5 m above the terrain
  float near = 0.0f;      // share within three rotor radii of the hub
  std::vector<Particle> particles;
};

struct Flight {
  float throttle = 0.85f, altitude = 9.0f;
  int frames = 150;
  bool solver = false;  // the live flow; false: the analytic downwash
  float rotorThrust = 1.0f;
  HelicopterModel model;
};

Dust fly(const Flight& flight) {
  AppConfig config = loadConfig(SANDSTORM_SOURCE_DIR "/config/downdraft.toml");
  config.particles.helicopter.throttle = flight.throttle;
  config.particles.helicopter.altitude = flight.altitude;
  config.particles.solver.enabled = flight.solver;
  config.particles.solver.rotorThrust = flight.rotorThrust;
  config.particles.solver.device = FluidDevice::Cpu;
  const auto terrain = makeTerrain(config.scene, config.path.parent_path());
  MainContext::Options options;
  options.fixedDt = 1.0f / 60.0f;
  MainContext main(config.particles, makeField(config.field, config.path.parent_path()).update,
                   options);
  HelicopterController helicopter(terrain, flight.model);
  helicopter.update(main);
  ParticleSystem system(main.initialState(),
                        ParticleSystem::Options{.capacity = config.run.capacity});
  system.setTerrain(terrain);
  // The live flow on the CPU's threads (FluidDriver, as solver.device = cpu
  // runs it): the same flow as each GPU's (GpuFluidSolverTest), far faster
  // than a GPU solver in software OpenGL.
  FluidDriver fluid(terrain);
  for (int f = 0; f < flight.frames; ++f) {
    const FramePacket packet = main.next();
    system.advance(packet);
    helicopter.update(main);
    fluid.update(main, packet);
  }
  Dust d;
  d.particles = system.update().readBack();
  const std::vector<Particle>& particles = d.particles;
  d.count = particles.size();
  const float r = HelicopterModel{}.rotorRadius;
  for (const Particle& p : particles) {
    const glm::vec3 x = p.position();
    if (x.z - terrain->heightAt({x.x, x.y}) > 1.5f) d.airborne += 1.0f;
    if (glm::length(glm::vec2(x)) < 3.0f * r) d.near += 1.0f;
  }
  if (d.count > 0) {
    d.airborne /= float(d.count);
    d.near /= float(d.count);
  }
  return d;
}

TEST_F(DowndraftTest, TheRotorWashRaisesDustUnderTheHelicopter) {
  const Dust hover = fly({});
  EXPECT_GT(hover.count, 20000u);
  EXPECT_GT(hover.airborne, 0.25f);  // rising, not lying on the ground
  EXPECT_GT(hover.near, 0.6f);       // around the rotor, not everywhere
  // Less throttle: less dust. Far above the ground: almost none.
  const Dust idle = fly({.throttle = 0.3f});
  EXPECT_LT(double(idle.count), 0.6 * double(hover.count));
  const Dust high = fly({.altitude = 40.0f});
  EXPECT_LT(double(high.count), 0.1 * double(hover.count));
}

// The live flow (the demo's default): after 5 s the dust near the ground
// moves outward with the wall jet, and beyond three rotor radii, where the jet
// slows and turns up, far more of it has risen than within two. With the
// rotor pushing no air (rotor_thrust 0) the dust neither spreads nor rises.
TEST_F(DowndraftTest, TheLiveFlowCarriesDustOutAlongTheGroundThenUp) {
  struct Reading {
    float outward = 0.0f;    // mean radial speed of the dust within 0.5 m of the ground
    float risenNear = 0.0f;  // share more than 1 m up, between 1 and 2 rotor radii
    float risenFar = 0.0f;   // the same beyond 3 rotor radii
  };
  const auto read = [](const Dust& d) {
    const auto terrain =
        makeTerrain(loadConfig(SANDSTORM_SOURCE_DIR "/config/downdraft.toml").scene,
                    SANDSTORM_SOURCE_DIR "/config/scenes");
    const float R = HelicopterModel{}.rotorRadius;
    Reading r;
    float low = 0.0f, nearCount = 0.0f, farCount = 0.0f;
    for (const Particle& p : d.particles) {
      const glm::vec3 x = p.position(), v = p.velocity();
      const float rho = glm::length(glm::vec2(x)), up = x.z - terrain->heightAt({x.x, x.y});
      if (up < 0.5f && rho > 1.0f) {
        r.outward += glm::dot(glm::vec2(v), glm::vec2(x)) / rho;
        low += 1.0f;
      }
      if (rho > R && rho < 2.0f * R) {
        nearCount += 1.0f;
        r.risenNear += up > 1.0f ? 1.0f : 0.0f;
      } else if (rho > 3.0f * R) {
        farCount += 1.0f;
        r.risenFar += up > 1.0f ? 1.0f : 0.0f;
      }
    }
    r.outward /= std::max(low, 1.0f);
    r.risenNear /= std::max(nearCount, 1.0f);
    r.risenFar /= std::max(farCount, 1.0f);
    std::printf(
        "outward %.2f m/s near the ground; risen > 1 m: %.2f at 1-2 R, %.2f beyond 3 R "
        "(%zu particles)\n",
        r.outward, r.risenNear, r.risenFar, d.count);
    return r;
  };
  HelicopterModel small;  // fewer grains, the same air
  small.maxParticles = 12000;
  small.maxRate = 4000.0f;
  const Reading live = read(fly({.frames = 300, .solver = true, .model = small}));
  EXPECT_GT(live.outward, 0.7f);  // 1.57 m/s measured; without thrust 0
  // Out along the ground and up, more the farther out (0.80 beyond 3 R)...
  EXPECT_GT(live.risenFar, 0.3f);
  EXPECT_GT(live.risenFar, live.risenNear);
  // ... and rolled back in near the rotor by the ring vortex (0.46 at 1-2 R):
  // the recirculation that makes a brownout.
  EXPECT_GT(live.risenNear, 0.2f);
  const Reading still =
      read(fly({.frames = 300, .solver = true, .rotorThrust = 0.0f, .model = small}));
  EXPECT_LT(std::abs(still.outward), 0.3f);
  EXPECT_LT(still.risenFar, 0.05f);
}

}  // namespace
}  // namespace sandstorm
