// OpacityShadowMap against the Beer-Lambert law (core/light/light_model.h):
// a uniform slab of particles lit from above lets exp(-n sigma d) of the
// light through at depth d; the ground darkens under a cloud and nowhere
// else; the lit haze (render.scattering) follows exp(-beta d) and is dimmer
// where the cloud shades it.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "contexts/render/wall_renderer.h"
#include "core/light/light_model.h"
#include "core/sim/main_context.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class OpacityShadowMapTest : public GlTest {};

// `count` still particles spread uniformly through a box (born in one frame).
ParticleState cloud(glm::vec3 center, glm::vec3 size, int count, float opacity, float diameter) {
  ParticleState s;
  s.emitters.clear();
  Emitter e;
  e.shape = EmitterShape::Box;
  e.position = center;
  e.width = size.x;
  e.depth = size.y;
  e.height = size.z;
  e.rate = float(count);  // dt = 1 s: exactly `count` births in the first frame
  e.lifetime = 1000.0f;
  s.emitters.push_back(e);
  s.sim.maximum = count;
  s.sim.groundCollision = false;
  s.render.size = diameter;
  s.render.opacityBirth = s.render.opacityDeath = opacity;
  s.render.shadows = true;
  s.render.lightDirection = {0.0f, 0.0f, 1.0f};
  return s;
}

TEST_F(OpacityShadowMapTest, ASlabOfDustLetsThroughExpOfMinusKTimesDepth) {
  const glm::vec3 center(0.0f, 0.0f, 3.0f), size(4.0f, 4.0f, 2.0f);
  const int count = 100000;
  const float opacity = 0.5f, diameter = 0.1f;
  // Both backends (the records and the live count the map reads), two densities.
  for (const auto& [backend, density] :
       {std::pair{"compute", 1.0f}, std::pair{"compute", 2.5f}, std::pair{"tf-gs", 1.0f}}) {
    SCOPED_TRACE(backend);
    ParticleState s = cloud(center, size, count, opacity, diameter);
    s.render.shadowDensity = density;
    MainContext::Options options;
    options.fixedDt = 1.0f;
    MainContext main(s, FieldUpdate{}, options);
    ParticleSystem system(s, {.capacity = std::size_t(count) + 1024, .backend = backend});
    system.advance(main.next());
    ASSERT_EQ(system.update().liveCount(), std::size_t(count));

    // k = n sigma: particles per cubic metre times each one's cross-section.
    const float k = float(count) / (size.x * size.y * size.z) *
                    particleCrossSection(diameter, opacity, density);
    const float top = center.z + 0.5f * size.z;
    for (float depth : {0.25f, 0.5f, 1.0f, 1.5f, 2.0f, 2.5f}) {
      std::vector<glm::vec3> points;
      for (int i = 0; i < 12; ++i)
        for (int j = 0; j < 12; ++j)
          points.push_back({-1.2f + 2.4f * i / 11.0f, -1.2f + 2.4f * j / 11.0f, top - depth});
      const std::vector<float> light = system.shadowMap()->transmittance(points);
      double tau = 0.0, mean = 0.0;
      for (float t : light) {
        tau += -std::log(double(t)) / double(light.size());
        mean += double(t) / double(light.size());
      }
      const double expected = double(k) * std::min(depth, size.z);
      std::printf(
          "%s, density %.1f, depth %.2f m: optical depth %.4f, expected k d = %.4f (%+.1f%%); "
          "light %.4f, exp(-k d) %.4f\n",
          backend, density, depth, tau, expected, 100.0 * (tau / expected - 1.0), mean,
          std::exp(-expected));
      EXPECT_NEAR(tau, expected, 0.05 * expected) << "depth " << depth;
      EXPECT_NEAR(mean, std::exp(-expected), 0.03) << "depth " << depth;
    }
    // Above the dust and beside it, all the light arrives.
    const std::vector<float> clear = system.shadowMap()->transmittance(
        {{0.0f, 0.0f, top + 0.5f}, {5.0f, 0.0f, 3.0f}, {0.0f, -5.0f, 1.0f}});
    for (float t : clear)
      EXPECT_EQ(t, 1.0f);
  }
}

TEST_F(OpacityShadowMapTest, WithShadowsOffAllTheLightArrives) {
  ParticleState s = cloud({0.0f, 0.0f, 3.0f}, {2.0f, 2.0f, 2.0f}, 5000, 0.8f, 0.1f);
  s.render.shadows = false;
  MainContext::Options options;
  options.fixedDt = 1.0f;
  MainContext main(s, FieldUpdate{}, options);
  ParticleSystem system(s, {.capacity = 8192});
  system.advance(main.next());
  for (float t : system.shadowMap()->transmittance({{0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 1.0f}}))
    EXPECT_EQ(t, 1.0f);
}

// Looking down on the ground from above; the light comes from +x at 45
// degrees, so a cloud 2 m up casts its shadow 2 m towards -x, away from
// where the cloud itself shows.
TEST_F(OpacityShadowMapTest, ACloudDarkensTheGroundAndTheHazeUnderItAndNowhereElse) {
  constexpr glm::ivec2 kSize{96, 64};
  const glm::vec3 eye(0.0f, -3.0f, 10.0f), target(0.0f), box(1.0f, 1.0f, 0.5f), center(0, 0, 2);
  WallSpec wall;
  wall.name = "above";
  wall.camera = CameraSpec{eye, target, 60.0f};
  wall.offscreenSize = kSize;
  auto image = [&](bool shadows, float scattering = 0.0f) {
    ParticleState s = cloud(center, box, 3000, 0.8f, 0.1f);
    s.render.lightDirection = {1.0f, 0.0f, 1.0f};
    s.render.shadows = shadows;
    s.render.scattering = scattering;
    MainContext::Options options;
    options.fixedDt = 1.0f;
    MainContext main(s, FieldUpdate{}, options);
    WallRenderer renderer({.wall = wall,
                           .initial = s,
                           .terrain = std::make_shared<HeightMap>(HeightMap::flat(0.0f)),
                           .capacity = 4096,
                           .nearPlane = 0.1f,
                           .farPlane = 100.0f});
    renderer.frame(main.next(), {0, 0});
    return renderer.capture();
  };
  const Image lit = image(false), shaded = image(true);

  const View v = perspectiveView(eye, target, {0, 0, 1}, glm::radians(60.0f),
                                 float(kSize.x) / float(kSize.y), 0.1f, 100.0f);
  const glm::mat4 inverse = glm::inverse(v.projection * v.view);
  // Where the ray through pixel (x, y) (rows top to bottom) meets the ground.
  auto ground = [&](int x, int y) {
    const glm::vec2 ndc((x + 0.5f) / kSize.x * 2.0f - 1.0f, 1.0f - (y + 0.5f) / kSize.y * 2.0f);
    const glm::vec4 far = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 dir = glm::normalize(glm::vec3(far) / far.w - eye);
    return eye + dir * (-eye.z / dir.z);
  };
  auto project = [&](glm::vec3 p) {
    const glm::vec4 clip = v.projection * v.view * glm::vec4(p, 1.0f);
    return glm::vec2((clip.x / clip.w * 0.5f + 0.5f) * kSize.x,
                     (0.5f - clip.y / clip.w * 0.5f) * kSize.y);
  };
  // The cloud's own pixels (its box's projection, with a particle's margin).
  glm::vec2 lo(1e9f), hi(-1e9f);
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 corner =
        center + (glm::vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1) - 0.5f) * (box + 0.1f);
    lo = glm::min(lo, project(corner));
    hi = glm::max(hi, project(corner));
  }
  auto cloudPixel = [&](int x, int y) {
    return x >= lo.x - 1 && x <= hi.x + 1 && y >= lo.y - 1 && y <= hi.y + 1;
  };
  // The shadow's footprint: the box's heights 1.75..2.25 m moved as far
  // along -x (x from -2.75 to -1.25), grown by two map cells and a radius.
  auto nearShadow = [](glm::vec3 g) {
    return std::abs(g.x + 2.0f) < 0.75f + 0.3f && std::abs(g.y) < 0.5f + 0.3f;
  };
  auto brightness = [](glm::u8vec4 c) { return float(c.x) + float(c.y) + float(c.z); };
  int inShadow = 0, darkened = 0;
  for (int y = 0; y < kSize.y; ++y)
    for (int x = 0; x < kSize.x; ++x) {
      if (cloudPixel(x, y)) continue;
      const glm::vec3 g = ground(x, y);
      if (!nearShadow(g)) {
        EXPECT_EQ(shaded.at(x, y), lit.at(x, y)) << "pixel " << x << ", " << y << " (ground " << g.x
                                                 << ", " << g.y << ") is not in the shadow";
      } else if (std::abs(g.x + 2.0f) < 0.5f && std::abs(g.y) < 0.35f) {
        ++inShadow;
        if (brightness(shaded.at(x, y)) < 0.75f * brightness(lit.at(x, y))) ++darkened;
      }
    }
  std::printf("%d of %d ground pixels well inside the shadow are darker\n", darkened, inShadow);
  EXPECT_GT(inShadow, 10);
  EXPECT_EQ(darkened, inShadow);

  // Light scattering: through d metres of haze of density beta the ground
  // keeps exp(-beta d) of its colour and the haze adds 0.85 (its albedo) of
  // the white light times 1 - exp(-beta d); less where the ray crosses the
  // dust's shadow, under the cloud.
  const float beta = 0.05f;
  const Image hazy = image(true, beta);
  // Whether the ray from the eye to g passes through air the cloud shades
  // (below its top, within a margin of its box seen along the light).
  auto crossesShadow = [&](glm::vec3 g) {
    for (int i = 0; i <= 200; ++i) {
      const glm::vec3 p = eye + (g - eye) * (float(i) / 200.0f);
      if (p.z > center.z + 0.5f * box.z + 0.3f) continue;
      const glm::vec3 q = p + glm::vec3(1.0f, 0.0f, 1.0f) * (center.z - p.z);
      if (std::abs(q.x) < 0.5f * box.x + 0.6f && std::abs(q.y) < 0.5f * box.y + 0.3f) return true;
    }
    return false;
  };
  int clear = 0, dimmed = 0;
  for (int y = 0; y < kSize.y; ++y)
    for (int x = 0; x < kSize.x; ++x) {
      if (cloudPixel(x, y)) continue;
      const glm::vec3 g = ground(x, y);
      const float seen = std::exp(-beta * glm::length(g - eye));
      const glm::vec3 expected =
          glm::vec3(shaded.at(x, y)) * seen + glm::vec3(0.85f * 255.0f * (1.0f - seen));
      const glm::vec3 got(hazy.at(x, y));
      if (!nearShadow(g) && !crossesShadow(g)) {
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(got[c], expected[c], 1.5f) << x << ", " << y;
        ++clear;
      } else if (std::abs(g.x + 2.0f) < 0.5f && std::abs(g.y) < 0.35f) {
        // The ray to this point crosses the shadow below the cloud (2 m of air).
        EXPECT_LT(got.y, expected.y - 2.0f) << x << ", " << y;
        ++dimmed;
      }
    }
  EXPECT_GT(clear, 1000);
  EXPECT_GT(dimmed, 10);
}

}  // namespace
}  // namespace sandstorm
