// The compute splat renderer against the billboard path it stands in for: the
// same particles, the same scene, images compared pixel by pixel within a
// stated tolerance; and render.mode = auto's choice by projected size.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "contexts/render/wall_renderer.h"
#include "core/sim/main_context.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class ParticleSplatTest : public GlTest, public ::testing::WithParamInterface<const char*> {};

constexpr glm::ivec2 kSize{128, 96};

// A ball of particles half sunk into the ground (which must hide the lower
// ones), seen from 8 m: a pixel is about 6 cm there.
ParticleState cloud(RenderMode mode, float size, bool twoColours) {
  ParticleState s;
  s.sim.maximum = 4000;
  s.sim.groundCollision = false;
  Emitter& e = s.emitters[0];
  e.shape = EmitterShape::Sphere;
  e.position = {0.0f, 0.0f, 0.6f};
  e.radius = 1.6f;
  e.rate = 3000.0f / 0.25f;  // everything in the first 0.25 s frame
  e.lifetime = 2.0f;
  e.lifetimeVariance = 1.0f;
  s.render.mode = mode;
  s.render.size = size;
  s.render.opacityBirth = 0.7f;
  s.render.opacityDeath = 0.4f;
  if (!twoColours) s.render.colorDeath = s.render.colorBirth;
  return s;
}

Image render(const ParticleState& state, const std::string& backend, int frames = 2,
             const GpuTuning& tuning = {}) {
  MainContext::Options options;
  options.fixedDt = 0.25f;
  options.seed = 3;
  MainContext main(state, FieldUpdate{}, options);
  WallSpec wall;
  wall.name = "test";
  wall.camera = CameraSpec{{0.0f, -8.0f, 1.2f}, {0.0f, 0.0f, 0.8f}, 40.0f};
  wall.offscreenSize = kSize;
  WallRenderer renderer(
      WallRendererSetup{.wall = wall,
                        .initial = state,
                        .terrain = std::make_shared<HeightMap>(HeightMap::flat(0.0f)),
                        .capacity = 4096,
                        .backend = backend,
                        .tuning = tuning,
                        .nearPlane = 0.1f,
                        .farPlane = 100.0f});
  for (int f = 0; f < frames; ++f) {
    FramePacket p = main.next();
    if (f > 0) p.emission.assign(p.emission.size(), 0u);  // one burst, then the same particles move
    renderer.frame(p, {0, 0});
  }
  return renderer.capture();
}

struct Difference {
  double mean = 0;    // mean |a - b| over pixels and RGB channels, 0..255
  double over16 = 0;  // fraction of pixels whose largest channel difference exceeds 16
  int largest = 0;
  double changed =
      0;  // fraction of pixels where the particles show at all (a differs from the empty scene)
};

Difference compare(const Image& a, const Image& b, const Image& empty) {
  Difference d;
  const int pixels = a.width * a.height;
  for (int i = 0; i < pixels; ++i) {
    int worst = 0, shows = 0;
    for (int c = 0; c < 3; ++c) {
      const int k = i * 4 + c;
      const int diff = std::abs(int(a.rgba[std::size_t(k)]) - int(b.rgba[std::size_t(k)]));
      d.mean += diff;
      worst = std::max(worst, diff);
      shows =
          std::max(shows, std::abs(int(a.rgba[std::size_t(k)]) - int(empty.rgba[std::size_t(k)])));
    }
    d.largest = std::max(d.largest, worst);
    if (worst > 16) d.over16 += 1;
    if (shows > 8) d.changed += 1;
  }
  d.mean /= 3.0 * pixels;
  d.over16 /= pixels;
  d.changed /= pixels;
  return d;
}

// render.shadows on, dense enough that the cloud shades itself deeply.
ParticleState shaded(ParticleState s) {
  s.render.shadows = true;
  s.render.shadowDensity = 20.0f;
  s.render.ambient = 0.2f;
  return s;
}

TEST_P(ParticleSplatTest, SplatsLookLikeBillboardsForSmallParticles) {
  for (int variant : {0, 1, 2}) {
    const bool twoColours = variant != 0, shadows = variant == 2;
    SCOPED_TRACE(shadows ? "shadows" : twoColours ? "colour varies with age" : "one colour");
    const float size = 0.18f;  // about 3 pixels across
    auto look = [&](RenderMode mode) {
      const ParticleState s = cloud(mode, size, twoColours);
      return shadows ? shaded(s) : s;
    };
    const Image billboards = render(look(RenderMode::Billboards), GetParam());
    const Image splats = render(look(RenderMode::Splat), GetParam());
    if (shadows) {  // the shadows show in both renderers
      ParticleState lit = look(RenderMode::Splat);
      lit.render.shadows = false;
      const Image litSplats = render(lit, GetParam());
      EXPECT_GT(compare(splats, litSplats, litSplats).changed, 0.05);
      lit.render.mode = RenderMode::Billboards;
      const Image litBillboards = render(lit, GetParam());
      EXPECT_GT(compare(billboards, litBillboards, litBillboards).changed, 0.05);
    }
    ParticleState none = cloud(RenderMode::Billboards, size, twoColours);
    none.emitters[0].rate = 0.0f;
    const Image empty = render(none, GetParam());
    const Difference d = compare(billboards, splats, empty);
    if (const char* dir = std::getenv("SANDSTORM_TEST_IMAGES")) {  // to look at them
      const std::string tag = std::string(GetParam()) + (shadows      ? "-shadows"
                                                         : twoColours ? "-two"
                                                                      : "-one");
      writePng(billboards, std::string(dir) + "/billboards-" + tag + ".png");
      writePng(splats, std::string(dir) + "/splats-" + tag + ".png");
    }
    std::printf(
        "%s, %s: mean |billboards - splats| %.2f/255, %.2f%% of pixels off by > 16, largest %d; "
        "particles "
        "cover %.1f%% of the image\n",
        GetParam(),
        shadows      ? "shadows"
        : twoColours ? "two colours"
                     : "one colour",
        d.mean, 100 * d.over16, d.largest, 100 * d.changed);
    // The stated tolerance: mean difference under 2/255 and under 2% of pixels
    // off by more than 16/255, where particles cover a good part of the image.
    EXPECT_GT(d.changed, 0.05);
    EXPECT_LT(d.mean, 2.0);
    EXPECT_LT(d.over16, 0.02);
  }
}

TEST_P(ParticleSplatTest, TiledAndAtomicSplatsAddTheSameSumsSoDrawTheSameImage) {
  // Plain, and with shadows and motion blur (their own programs).
  for (bool extras : {false, true}) {
    ParticleState state = cloud(RenderMode::Splat, 0.25f, true);
    if (extras) {
      state = shaded(state);
      state.render.shutter = 0.2f;
    }
    SCOPED_TRACE(extras ? "shadows and motion blur" : "plain");
    const Image atomic = render(state, GetParam(), 2, GpuTuning{.splat = GpuTuning::Splat::Atomic});
    ParticleState none = state;
    none.emitters[0].rate = 0.0f;
    EXPECT_FALSE(atomic.rgba == render(none, GetParam()).rgba);
    // The tiled variant, as it runs; with chunks of 37 records (dense tiles
    // split over several workgroups, which add their sums with atomics); with
    // lists that hold 500 records (the scatter pass adds the rest); and both.
    const std::vector<std::pair<std::size_t, std::size_t>> variants{
        {8192, 0}, {37, 0}, {8192, 500}, {37, 500}};
    for (const auto& [chunk, list] : variants) {
      const Image tiled =
          render(state, GetParam(), 2, GpuTuning{.splatChunk = chunk, .splatList = list});
      EXPECT_TRUE(tiled.rgba == atomic.rgba) << "chunk " << chunk << ", list " << list;
    }
  }
}

TEST_P(ParticleSplatTest, AutoSplatsSmallParticlesAndDrawsLargeOnesAsBillboards) {
  const Image smallAuto = render(cloud(RenderMode::Auto, 0.18f, true), GetParam());
  const Image smallSplat = render(cloud(RenderMode::Splat, 0.18f, true), GetParam());
  EXPECT_TRUE(smallAuto.rgba == smallSplat.rgba);  // 3 pixels <= render.splat_pixels (4)
  const Image largeAuto = render(cloud(RenderMode::Auto, 0.6f, true), GetParam());
  const Image largeBillboards = render(cloud(RenderMode::Billboards, 0.6f, true), GetParam());
  EXPECT_TRUE(largeAuto.rgba == largeBillboards.rgba);  // 10 pixels
}

INSTANTIATE_TEST_SUITE_P(Backends, ParticleSplatTest, ::testing::Values("tf-gs", "compute"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param) == "tf-gs"
                                      ? std::string("TransformFeedback")
                                      : std::string("Compute");
                         });

}  // namespace
}  // namespace sandstorm
