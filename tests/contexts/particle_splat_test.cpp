// The compute splat renderer against the billboard path it stands in for: the
// same particles, the same scene, images compared pixel by pixel within a
// stated tolerance; and render.mode = auto's choice by projected size.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "contexts/render/wall_renderer.h"
#include "core/field/analytic_field.h"
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

const CameraSpec kCamera{{0.0f, -8.0f, 1.2f}, {0.0f, 0.0f, 0.8f}, 40.0f};

Image render(const ParticleState& state, const std::string& backend, int frames = 2,
             const GpuTuning& tuning = {}, std::shared_ptr<const VectorField> field = nullptr,
             const CameraSpec& camera = kCamera, HeightMap terrain = HeightMap::flat(0.0f)) {
  MainContext::Options options;
  options.fixedDt = 0.25f;
  options.seed = 3;
  MainContext main(state, FieldUpdate{.field = std::move(field)}, options);
  WallSpec wall;
  wall.name = "test";
  wall.camera = camera;
  wall.offscreenSize = kSize;
  WallRenderer renderer(
      WallRendererSetup{.wall = wall,
                        .initial = state,
                        .terrain = std::make_shared<HeightMap>(std::move(terrain)),
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

// Particles of 10, 25 and 40 pixels (the last beyond the 31 a splat may span
// on one grid): splats at least twice render.splat_detail wide are drawn on
// coarser grids and upsampled. Up to 31 pixels the image is the
// full-resolution splats' sampled more coarsely, and is compared with it
// (splats differ from billboards by their averaged normals already, 1.9/255
// at 10 pixels); at 40 pixels with the billboards, which full-resolution
// splats cannot draw (they draw them 31 pixels wide).
TEST_P(ParticleSplatTest, LargeSplatsOnCoarserGridsLookLikeSplatsAtFullResolution) {
  for (float size : {0.6f, 1.5f, 2.4f}) {
    SCOPED_TRACE(size);
    ParticleState splat = cloud(RenderMode::Splat, size, true);
    splat.render.splatOverlap = 0.0f;  // each splat on its own level (the next test coarsens)
    ASSERT_GT(splat.render.splatDetail, 0.0f);
    const Image levels = render(splat, GetParam());
    ParticleState none = splat;
    none.emitters[0].rate = 0.0f;
    const Image empty = render(none, GetParam());
    splat.render.splatDetail = 0.0f;
    const Image full = render(splat, GetParam());
    const Image billboards = render(cloud(RenderMode::Billboards, size, true), GetParam());
    const Difference fromFull = compare(full, levels, empty);
    const Difference fromBillboards = compare(billboards, levels, empty);
    const Difference clamped = compare(billboards, full, empty);
    std::printf(
        "%s, %.1f m (~%.0f px): splats on levels against full resolution: mean %.2f/255, %.2f%% "
        "of pixels off by > 16; against billboards %.2f, %.2f%% (full resolution against "
        "billboards %.2f, %.2f%%)\n",
        GetParam(), size, size / 0.06f, fromFull.mean, 100 * fromFull.over16, fromBillboards.mean,
        100 * fromBillboards.over16, clamped.mean, 100 * clamped.over16);
    if (const char* dir = std::getenv("SANDSTORM_TEST_IMAGES")) {
      const std::string tag = std::string(GetParam()) + "-" + std::to_string(int(size * 10));
      writePng(billboards, std::string(dir) + "/large-billboards-" + tag + ".png");
      writePng(levels, std::string(dir) + "/large-levels-" + tag + ".png");
      writePng(full, std::string(dir) + "/large-full-" + tag + ".png");
    }
    EXPECT_FALSE(levels.rgba == full.rgba);  // the levels ran
    EXPECT_GT(fromFull.changed, 0.05);
    if (size < 2.0f) {
      EXPECT_LT(fromFull.mean, 1.5);
      EXPECT_LT(fromFull.over16, 0.05);
    } else {
      EXPECT_LT(fromBillboards.mean, 0.85 * clamped.mean);
      EXPECT_LT(fromBillboards.over16, 0.85 * clamped.over16);
    }
  }
}

// Dense tiles drawn on a coarser grid (render.splat_overlap): the cloud seen
// from 3 m, so that it fills the view, its particles about 12 pixels wide,
// with the limit at 4 splats a pixel (the default is 64; 4000 particles cover
// a pixel some 10 times), so that tiles with the cloud all around them draw
// one grid coarser, against every splat on its own level. The same sums
// sampled more coarsely: close to it (what differs is the particles' grain,
// which this sparse a cloud still shows), not the same; with the limit above
// the cloud's overlap, the same. Whether the chunks are split or the lists
// overflow (the scatter pass then adds a record itself, on the grid the tile
// draws on), the tiled pass adds the same integers.
TEST_P(ParticleSplatTest, DenseTilesOnACoarserGridLookLikeEverySplatOnItsOwnLevel) {
  ParticleState state = cloud(RenderMode::Splat, 0.3f, true);
  state.render.splatOverlap = 0.0f;
  const CameraSpec near{{0.0f, -3.0f, 0.9f}, {0.0f, 0.0f, 0.8f}, 40.0f};
  const Image exact = render(state, GetParam(), 2, {}, nullptr, near);
  ParticleState none = state;
  none.emitters[0].rate = 0.0f;
  const Image empty = render(none, GetParam(), 2, {}, nullptr, near);
  state.render.splatOverlap = 4.0f;
  const Image coarser = render(state, GetParam(), 2, {}, nullptr, near);
  const Difference d = compare(exact, coarser, empty);
  std::printf(
      "%s: dense tiles one grid coarser against every splat on its own level: mean "
      "%.2f/255, %.2f%% of pixels off by > 16, largest %d; particles cover %.1f%%\n",
      GetParam(), d.mean, 100 * d.over16, d.largest, 100 * d.changed);
  if (const char* dir = std::getenv("SANDSTORM_TEST_IMAGES")) {
    writePng(exact, std::string(dir) + "/dense-exact-" + GetParam() + ".png");
    writePng(coarser, std::string(dir) + "/dense-coarser-" + GetParam() + ".png");
  }
  EXPECT_FALSE(coarser.rgba == exact.rgba);  // the tiles did draw coarser
  EXPECT_GT(d.changed, 0.05);
  EXPECT_LT(d.mean, 5.0);
  EXPECT_LT(d.over16, 0.03);
  ParticleState sparse = state;
  sparse.render.splatOverlap = 1000.0f;
  EXPECT_TRUE(render(sparse, GetParam(), 2, {}, nullptr, near).rgba == exact.rgba);
  const std::vector<std::pair<std::size_t, std::size_t>> variants{{37, 0}, {8192, 500}, {37, 500}};
  for (const auto& [chunk, list] : variants) {
    const Image tiled = render(state, GetParam(), 2,
                               GpuTuning{.splatChunk = chunk, .splatList = list}, nullptr, near);
    EXPECT_TRUE(tiled.rgba == coarser.rgba) << "chunk " << chunk << ", list " << list;
  }
}

TEST_P(ParticleSplatTest, TiledAndAtomicSplatsAddTheSameSumsSoDrawTheSameImage) {
  // Plain, with shadows and motion blur (their own programs), and particles
  // large enough to go to coarser grids (render.splat_detail).
  // Motion blur by the filter adds motion sums of its own (variant 3, with levels).
  // Variant 4 moves the cloud mostly out of the view: where at most half of
  // a binning workgroup's particles are in view, the scatter pass visits
  // only those the count pass listed. Variant 5 cuts the cloud with ground
  // sloping across the view, so the scene's depth under the splats (the
  // soft depth test's) changes along rows as well as columns.
  for (int variant : {0, 1, 2, 3, 4, 5}) {
    ParticleState state =
        cloud(RenderMode::Splat, variant == 2 || variant == 3 ? 0.9f : 0.25f, true);
    if (variant == 1) {
      state = shaded(state);
      state.render.shutter = 0.2f;
      state.render.blur = BlurMethod::Smear;
    }
    if (variant == 3) {
      state.render.shutter = 0.2f;
      state.render.blur = BlurMethod::Filter;
      state.emitters[0].velocity = {2.0f, 0.0f, 1.0f};
      state.emitters[0].spread = 1.5f;
    }
    if (variant == 4) state.emitters[0].position.x = 4.6f;  // the view's edge at 8 m: 3.88 m
    state.render.splatOverlap = 0.0f;  // the atomic variant draws no tile coarser
    SCOPED_TRACE(variant == 0   ? "plain"
                 : variant == 1 ? "shadows and motion blur"
                 : variant == 2 ? "levels"
                 : variant == 3 ? "levels and motion blur by the filter"
                 : variant == 4 ? "most of the cloud out of view"
                                : "ground sloping across the view through the cloud");
    // Rising 0.4 m a metre to the right (+x) and 0.2 m a metre away (+y).
    const HeightMap ground = variant == 5 ? HeightMap({-20.0f, -20.0f}, {20.0f, 20.0f}, {2, 2},
                                                      {-12.0f, 4.0f, -4.0f, 12.0f})
                                          : HeightMap::flat(0.0f);
    const auto draw = [&](const ParticleState& s, const GpuTuning& tuning) {
      return render(s, GetParam(), 2, tuning, nullptr, kCamera, ground);
    };
    const Image atomic = draw(state, GpuTuning{.splat = GpuTuning::Splat::Atomic});
    ParticleState none = state;
    none.emitters[0].rate = 0.0f;
    EXPECT_FALSE(atomic.rgba == draw(none, {}).rgba);
    // The tiled variant, as it runs; with chunks of 37 records (dense tiles
    // split over several workgroups, which add their sums with atomics); with
    // lists that hold 500 records (the scatter pass adds the rest); and both.
    const std::vector<std::pair<std::size_t, std::size_t>> variants{
        {8192, 0}, {37, 0}, {8192, 500}, {37, 500}};
    for (const auto& [chunk, list] : variants) {
      const Image tiled = draw(state, GpuTuning{.splatChunk = chunk, .splatList = list});
      EXPECT_TRUE(tiled.rgba == atomic.rgba) << "chunk " << chunk << ", list " << list;
    }
  }
}

// A stereo wall's two eyes 6 m apart (each eye's image half as wide, as a side-by-side display
// stretches it), side by side in one image.
Image renderEyes(const ParticleState& state, const std::string& backend, const GpuTuning& tuning) {
  MainContext::Options options;
  options.fixedDt = 0.25f;
  options.seed = 3;
  MainContext main(state, FieldUpdate{}, options);
  WallSpec wall;
  wall.name = "test";
  wall.camera = kCamera;
  wall.stereo = StereoMode::SideBySide;
  wall.offscreenSize = {2 * kSize.x, kSize.y};
  WallRenderer renderer(WallRendererSetup{.wall = wall,
                                          .initial = state,
                                          .capacity = 4096,
                                          .backend = backend,
                                          .tuning = tuning,
                                          .nearPlane = 0.1f,
                                          .farPlane = 100.0f});
  for (int f = 0; f < 2; ++f) {
    FramePacket p = main.next();
    p.viewer.head.eyeSeparation = 6.0f;
    renderer.frame(p, {0, 0});
  }
  return renderer.capture();
}

// The first eye's binning lists the particles that may show in the second
// eye's view, and the second eye's visits only those (SplatViews): the
// cloud lies beyond the first eye's view and a fifth of it in the second's,
// some splats across that view's edge, so a list made from the first eye's
// view, or without the splats' reach, leaves particles out of the second.
// With motion blur's smears (variant 2) the particles fly away from the
// second eye's view, their smears reaching back into it further than a
// still splat's reach.
TEST_P(ParticleSplatTest, AWallsSecondEyeDrawsWhatItSeesFromTheParticlesTheFirstListed) {
  for (int variant : {0, 1, 2}) {
    SCOPED_TRACE(variant == 0 ? "small splats" : variant == 1 ? "large splats" : "smeared splats");
    ParticleState state = cloud(RenderMode::Splat, variant == 1 ? 0.9f : 0.25f, true);
    state.emitters[0].position.x = 12.0f;  // the eyes see up to 4.8 and 10.8 m to the right at 8 m
    state.render.splatOverlap = 0.0f;      // the atomic variant draws no tile coarser
    if (variant == 2) {
      // 2 m a frame: the cloud moves from 11 to 13 m; a smear of 4 m, about 33 pixels.
      state.emitters[0].position.x = 11.0f;
      state.emitters[0].velocity = {8.0f, 0.0f, 0.0f};
      state.emitters[0].spread = 0.0f;
      state.sim.motion = MotionModel::Force;  // no field, no gravity: they keep their speed
      state.sim.gravity = glm::vec3(0.0f);
      state.render.shutter = 0.5f;
      state.render.blur = BlurMethod::Smear;
    }
    const Image atomic =
        renderEyes(state, GetParam(), GpuTuning{.splat = GpuTuning::Splat::Atomic});
    const Image tiled = renderEyes(state, GetParam(), GpuTuning{});
    ParticleState none = state;
    none.emitters[0].rate = 0.0f;
    const Image empty = renderEyes(none, GetParam(), GpuTuning{});
    // The second eye (the image's right half) shows the cloud; the first none of it.
    int first = 0, second = 0;
    for (int y = 0; y < kSize.y; ++y)
      for (int x = 0; x < 2 * kSize.x; ++x) {
        const std::size_t i = std::size_t(y * 2 * kSize.x + x) * 4;
        const bool differs = atomic.rgba[i] != empty.rgba[i] ||
                             atomic.rgba[i + 1] != empty.rgba[i + 1] ||
                             atomic.rgba[i + 2] != empty.rgba[i + 2];
        (x < kSize.x ? first : second) += differs ? 1 : 0;
      }
    if (const char* dir = std::getenv("SANDSTORM_TEST_IMAGES"))
      writePng(atomic,
               std::string(dir) + "/eyes-" + GetParam() + "-" + std::to_string(variant) + ".png");
    EXPECT_EQ(first, 0);
    EXPECT_GT(second, 100);
    EXPECT_TRUE(tiled.rgba == atomic.rgba);
  }
}

// Trails in the tiled variant's runs of pixels a tile add the same integers
// as the atomic variant's segments: the cloud turning about the z axis, its
// trails of 8 positions several pixels a segment, crossing the 32-pixel tiles.
TEST_P(ParticleSplatTest, TiledAndAtomicTrailsAddTheSameSumsSoDrawTheSameImage) {
  struct Spin final : AnalyticField {  // 1 rad/s: 0.4 m a frame at 1.6 m, about 9 pixels
    glm::vec3 evaluate(const glm::vec3& p) const override { return {-p.y, p.x, 0.0f}; }
  };
  auto field = std::make_shared<VectorField>(bake(Spin(), Box{{-5, -5, -5}, {5, 5, 5}}, {6, 6, 3}));
  constexpr int kFrames = 12;
  // Splat views add the trails to the splats; billboard views blend them
  // over the scene by the same passes.
  for (const auto& [mode, shadows] :
       {std::pair{RenderMode::Splat, false}, std::pair{RenderMode::Splat, true},
        std::pair{RenderMode::Billboards, false}}) {
    ParticleState state = cloud(mode, 0.1f, true);
    state.sim.maximum = 1500;
    state.emitters[0].rate = 1000.0f / 0.25f;
    state.emitters[0].lifetime = 10.0f;
    if (shadows) state = shaded(state);
    SCOPED_TRACE(mode == RenderMode::Billboards ? "billboards" : shadows ? "shadows" : "plain");
    const GpuTuning atomicTuning{.splat = GpuTuning::Splat::Atomic};
    const Image without = render(state, GetParam(), kFrames, atomicTuning, field);
    state.render.trailLength = 8;
    const Image atomic = render(state, GetParam(), kFrames, atomicTuning, field);
    EXPECT_FALSE(atomic.rgba == without.rgba) << "the trails show";
    // The tiled variant, as it runs; with chunks of 37 runs (several
    // workgroups a tile, adding with atomics); with lists of 500 runs (the
    // scatter pass adds the rest with global atomics); and both.
    const std::vector<std::pair<std::size_t, std::size_t>> variants{
        {8192, 0}, {37, 0}, {8192, 500}, {37, 500}};
    for (const auto& [chunk, list] : variants) {
      const Image tiled = render(
          state, GetParam(), kFrames,
          GpuTuning{
              .splatChunk = chunk, .splatList = list, .trailPass = GpuTuning::TrailPass::Tiled},
          field);
      EXPECT_TRUE(tiled.rgba == atomic.rgba) << "chunk " << chunk << ", list " << list;
    }
    // The tiled splats with atomic trails, and with the choice of the two
    // as it goes (it tries them in blocks of 8 views: both run in these frames).
    for (const GpuTuning::TrailPass pass :
         {GpuTuning::TrailPass::Atomic, GpuTuning::TrailPass::Auto}) {
      const Image image = render(state, GetParam(), kFrames, GpuTuning{.trailPass = pass}, field);
      EXPECT_TRUE(image.rgba == atomic.rgba) << "trail pass " << int(pass);
    }
  }
}

// Motion blur by the filter (render.blur = filter) against each splat smeared
// along its own path (smear, exact for a box shutter), the cloud carried by
// a wind (paths side by side, about 13 pixels long), and turning about the
// z axis (paths every way, crossing where the near and the far side of the
// cloud overlap; each pixel takes one axis, so crossing paths are gathered
// in part: the filter's approximation), and in the wind with render.shadows
// (the light buffer blurred as well). The stated tolerance: in the wind the
// filter is within 1/255 of the smear on average, a quarter of the still
// image's difference; turning, closer than 0.75 of the still image's.
TEST_P(ParticleSplatTest, MotionBlurByTheFilterLooksLikeEachSplatSmeared) {
  struct Wind final : AnalyticField {  // 0.75 m in the 0.25 s shutter
    glm::vec3 evaluate(const glm::vec3&) const override { return {3.0f, 0.0f, 0.3f}; }
  };
  struct Spin final : AnalyticField {  // 2 rad/s: 0.8 m in the shutter at 1.6 m
    glm::vec3 evaluate(const glm::vec3& p) const override { return {-2 * p.y, 2 * p.x, 0.3f}; }
  };
  // In a wind again with render.shadows: the light buffer is blurred too.
  for (const auto& [turning, shadows] :
       {std::pair{false, false}, std::pair{true, false}, std::pair{false, true}}) {
    SCOPED_TRACE(turning ? "turning" : shadows ? "in a wind, shadowed" : "in a wind");
    auto field = std::make_shared<VectorField>(
        turning ? bake(Spin(), Box{{-5, -5, -5}, {5, 5, 5}}, {6, 6, 3})
                : bake(Wind(), Box{{-5, -5, -5}, {5, 5, 5}}, {2, 2, 2}));
    ParticleState state = cloud(RenderMode::Splat, 0.2f, true);
    state.sim.maximum = 1500;
    state.emitters[0].rate = 1000.0f / 0.25f;
    state.emitters[0].lifetime = 10.0f;
    if (shadows) state = shaded(state);
    const Image still = render(state, GetParam(), 3, {}, field);
    ParticleState none = state;
    none.emitters[0].rate = 0.0f;
    const Image empty = render(none, GetParam(), 3, {}, field);
    state.render.shutter = 0.25f;
    state.render.blur = BlurMethod::Smear;
    const Image smear = render(state, GetParam(), 3, {}, field);
    state.render.blur = BlurMethod::Filter;
    const Image filter = render(state, GetParam(), 3, {}, field);
    const Difference fromSmear = compare(filter, smear, empty),
                     stillFromSmear = compare(still, smear, empty);
    const double covered = compare(smear, smear, empty).changed;
    std::printf(
        "%s, %s: filter against smear: mean %.2f/255, %.2f%% of pixels off by > 16, largest %d; "
        "still against smear: mean %.2f, %.2f%%; the smears cover %.1f%% of the image\n",
        GetParam(),
        turning   ? "turning"
        : shadows ? "wind, shadowed"
                  : "wind",
        fromSmear.mean, 100 * fromSmear.over16, fromSmear.largest, stillFromSmear.mean,
        100 * stillFromSmear.over16, 100 * covered);
    if (const char* dir = std::getenv("SANDSTORM_TEST_IMAGES")) {
      const std::string tag = std::string(turning   ? "turning-"
                                          : shadows ? "shadowed-"
                                                    : "wind-") +
                              GetParam();
      writePng(still, std::string(dir) + "/blur-still-" + tag + ".png");
      writePng(smear, std::string(dir) + "/blur-smear-" + tag + ".png");
      writePng(filter, std::string(dir) + "/blur-filter-" + tag + ".png");
    }
    EXPECT_GT(covered, 0.1);
    if (turning) {
      EXPECT_LT(fromSmear.mean, 0.75 * stillFromSmear.mean);
      EXPECT_LT(fromSmear.over16, 0.75 * stillFromSmear.over16);
    } else {
      EXPECT_LT(fromSmear.mean, 1.0);
      EXPECT_LT(fromSmear.mean, 0.25 * stillFromSmear.mean);
      EXPECT_LT(fromSmear.over16, 0.005);
    }
  }
}

TEST_P(ParticleSplatTest, AutoSplatsParticlesUpToSplatPixelsAndDrawsLargerOnesAsBillboards) {
  const Image smallAuto = render(cloud(RenderMode::Auto, 0.18f, true), GetParam());
  const Image smallSplat = render(cloud(RenderMode::Splat, 0.18f, true), GetParam());
  EXPECT_TRUE(smallAuto.rgba == smallSplat.rgba);  // 3 pixels
  // 10 pixels: splats (on a coarser grid) while render.splat_pixels allows.
  ParticleState large = cloud(RenderMode::Auto, 0.6f, true);
  const Image largeAuto = render(large, GetParam());
  const Image largeSplat = render(cloud(RenderMode::Splat, 0.6f, true), GetParam());
  EXPECT_TRUE(largeAuto.rgba == largeSplat.rgba);
  large.render.splatPixels = 8.0f;
  const Image largeAutoBillboards = render(large, GetParam());
  const Image largeBillboards = render(cloud(RenderMode::Billboards, 0.6f, true), GetParam());
  EXPECT_TRUE(largeAutoBillboards.rgba == largeBillboards.rgba);
}

INSTANTIATE_TEST_SUITE_P(Backends, ParticleSplatTest, ::testing::Values("tf-gs", "compute"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param) == "tf-gs"
                                      ? std::string("TransformFeedback")
                                      : std::string("Compute");
                         });

}  // namespace
}  // namespace sandstorm
