// The downdraft demo (thesis chapter 6), end to end on the GPU: the rotor wash
// raises dust from the terrain under the helicopter, and the throttle and
// altitude controls drive how much.
#include <gtest/gtest.h>

#include <algorithm>

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
};

Dust fly(float throttle, float altitude, int frames) {
  AppConfig config = loadConfig(SANDSTORM_SOURCE_DIR "/config/downdraft.toml");
  config.particles.helicopter.throttle = throttle;
  config.particles.helicopter.altitude = altitude;
  const auto terrain = makeTerrain(config.scene, config.path.parent_path());
  MainContext::Options options;
  options.fixedDt = 1.0f / 60.0f;
  MainContext main(config.particles, makeField(config.field, config.path.parent_path()).update,
                   options);
  HelicopterController helicopter(terrain);
  helicopter.update(main);
  ParticleSystem system(main.initialState(),
                        ParticleSystem::Options{.capacity = config.run.capacity});
  system.setTerrain(terrain);
  for (int f = 0; f < frames; ++f) {
    system.advance(main.next());
    helicopter.update(main);
  }
  Dust d;
  const std::vector<Particle> particles = system.update().readBack();
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
  const Dust hover = fly(0.85f, 9.0f, 150);
  EXPECT_GT(hover.count, 20000u);
  EXPECT_GT(hover.airborne, 0.25f);  // rising, not lying on the ground
  EXPECT_GT(hover.near, 0.6f);       // around the rotor, not everywhere
  // Less throttle: less dust. Far above the ground: almost none.
  const Dust idle = fly(0.3f, 9.0f, 150);
  EXPECT_LT(double(idle.count), 0.6 * double(hover.count));
  const Dust high = fly(0.85f, 40.0f, 150);
  EXPECT_LT(double(high.count), 0.1 * double(hover.count));
}

}  // namespace
}  // namespace sandstorm
