// Headless render tests: what the pixels show, checked against where the
// particles must be (their projected positions), what must hide them (the
// ground) and how premultiplied "over" blending must combine them.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "contexts/render/wall_renderer.h"
#include "core/field/analytic_field.h"
#include "core/sim/main_context.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class RenderTest : public GlTest {};

constexpr glm::ivec2 kSize{96, 64};

struct Uniform final : AnalyticField {
  glm::vec3 v;
  explicit Uniform(glm::vec3 value) : v(value) {}
  glm::vec3 evaluate(const glm::vec3&) const override { return v; }
};

WallSpec cameraWall() {
  WallSpec w;
  w.name = "test";
  w.camera = CameraSpec{{0.0f, -8.0f, 2.0f}, {0.0f, 0.0f, 2.0f}, 40.0f};
  w.offscreenSize = kSize;
  return w;
}

// A particle state whose emitters each emit exactly one particle per 0.25 s
// frame (rate * dt = 1, and stochastic rounding of a whole number is exact).
ParticleState onePerFrame(std::vector<glm::vec3> positions, float opacity) {
  ParticleState s;
  s.emitters.clear();
  for (const glm::vec3& p : positions) {
    Emitter e;
    e.shape = EmitterShape::Point;
    e.position = p;
    e.rate = 4.0f;
    e.lifetime = 100.0f;
    s.emitters.push_back(e);
  }
  s.sim.groundCollision = false;
  s.render.mode = RenderMode::Billboards;
  s.render.size = 1.0f;
  s.render.colorBirth = s.render.colorDeath = {0.9f, 0.1f, 0.1f};
  s.render.opacityBirth = s.render.opacityDeath = opacity;
  s.render.ambient = 1.0f;  // unlit: colour is exactly the attribute
  return s;
}

Image render(const ParticleState& state, int frames,
             std::shared_ptr<const VectorField> field = nullptr,
             const std::string& backend = "compute") {
  MainContext::Options options;
  options.fixedDt = 0.25f;
  MainContext main(state, FieldUpdate{.field = field}, options);
  WallRendererSetup setup{.wall = cameraWall(),
                          .initial = state,
                          .terrain = std::make_shared<HeightMap>(HeightMap::flat(0.0f)),
                          .capacity = 4096,
                          .backend = backend,
                          .nearPlane = 0.1f,
                          .farPlane = 100.0f};
  WallRenderer wall(setup);
  for (int f = 0; f < frames; ++f)
    wall.frame(main.next(), {0, 0});
  return wall.capture();
}

// Where p lands in the image, in pixels (rows top to bottom).
glm::vec2 projectExactly(const glm::vec3& p) {
  const WallSpec w = cameraWall();
  const View v =
      perspectiveView(w.camera->position, w.camera->target, {0, 0, 1}, glm::radians(40.0f),
                      float(kSize.x) / float(kSize.y), 0.1f, 100.0f);
  const glm::vec4 clip = v.projection * v.view * glm::vec4(p, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * kSize.x, (0.5f - ndc.y * 0.5f) * kSize.y};
}

// The pixel p lands in.
glm::ivec2 project(const glm::vec3& p) {
  return glm::ivec2(projectExactly(p));
}

float redness(glm::u8vec4 c) {
  return float(c.x) - 0.5f * (float(c.y) + float(c.z));
}

TEST_F(RenderTest, ParticlesAppearWhereTheyAreAndNowhereElse) {
  const glm::vec3 where(1.5f, 0.0f, 2.5f);
  const Image empty = render(onePerFrame({}, 0.8f), 1);
  const Image one = render(onePerFrame({where}, 0.8f), 1);
  const glm::ivec2 px = project(where);
  EXPECT_GT(redness(one.at(px.x, px.y)), redness(empty.at(px.x, px.y)) + 80.0f);
  // Far from the particle, nothing changed.
  const glm::ivec2 far = project({-2.5f, 0.0f, 1.0f});
  EXPECT_EQ(one.at(far.x, far.y), empty.at(far.x, far.y));
}

// One particle born at the first frame (the emitter then stops), after
// `frames` frames of 0.25 s.
Image oneParticleAfter(ParticleState s, std::shared_ptr<const VectorField> field, int frames) {
  MainContext::Options options;
  options.fixedDt = 0.25f;
  MainContext main(s, FieldUpdate{.field = field}, options);
  WallRendererSetup setup{.wall = cameraWall(),
                          .initial = s,
                          .terrain = std::make_shared<HeightMap>(HeightMap::flat(0.0f)),
                          .capacity = 4096,
                          .nearPlane = 0.1f,
                          .farPlane = 100.0f};
  WallRenderer wall(setup);
  wall.frame(main.next(), {0, 0});   // born at the emitter
  main.set("emitter.0.rate", 0.0f);  // no more births
  for (int f = 1; f < frames; ++f)
    wall.frame(main.next(), {0, 0});
  return wall.capture();
}

TEST_F(RenderTest, TheFieldCarriesParticlesToWhereItSays) {
  // Tracer in a uniform field of 1 m/s along x: born at x = -2, after 3 s at x = +1.
  auto field = std::make_shared<VectorField>(
      bake(Uniform({1.0f, 0, 0}), Box{{-5, -5, 0}, {5, 5, 5}}, {2, 2, 2}));
  ParticleState first = onePerFrame({{-2.0f, 0.0f, 2.5f}}, 0.8f);
  first.emitters[0].lifetime = 100.0f;
  const Image image = oneParticleAfter(first, field, 13);  // t = 0, then 12 x 0.25 s
  const glm::ivec2 now = project({1.0f, 0.0f, 2.5f}), then = project({-2.0f, 0.0f, 2.5f});
  EXPECT_GT(redness(image.at(now.x, now.y)), 60.0f);
  EXPECT_LT(redness(image.at(then.x, then.y)), 20.0f);
}

TEST_F(RenderTest, TheGroundHidesParticlesBelowIt) {
  const Image empty = render(onePerFrame({}, 0.8f), 1);
  const Image buried =
      render(onePerFrame({{0.0f, 0.0f, -0.8f}}, 0.8f), 1);  // 1 m billboard, fully underground
  EXPECT_EQ(empty.rgba, buried.rgba);
  // A particle half in the ground shows above it and not below it.
  const Image half = render(onePerFrame({{0.0f, 0.0f, 0.0f}}, 0.8f), 1);
  const glm::ivec2 above = project({0.0f, 0.0f, 0.3f}), below = project({0.0f, 0.0f, -0.3f});
  EXPECT_GT(redness(half.at(above.x, above.y)), redness(empty.at(above.x, above.y)) + 20.0f);
  EXPECT_EQ(half.at(below.x, below.y), empty.at(below.x, below.y));
}

TEST_F(RenderTest, CoincidentParticlesBlendAsPremultipliedOver) {
  // One layer of opacity a over background b gives p1 = c a + b (1 - a); two
  // layers give p2 = c - (c - b)(1 - a)^2. Measure a from p1, predict p2.
  const glm::vec3 where(0.0f, 0.0f, 2.0f);
  const Image empty = render(onePerFrame({}, 0.4f), 1);
  const Image one = render(onePerFrame({where}, 0.4f), 1);
  const Image two = render(onePerFrame({where, where}, 0.4f), 1);
  const glm::ivec2 px = project(where);
  const glm::vec3 c = glm::vec3(0.9f, 0.1f, 0.1f) * 255.0f;
  const glm::vec3 b(empty.at(px.x, px.y)), p1(one.at(px.x, px.y)), p2(two.at(px.x, px.y));
  const float a = (p1.x - b.x) / (c.x - b.x);
  ASSERT_GT(a, 0.1f);
  ASSERT_LT(a, 0.6f);
  for (int ch = 0; ch < 3; ++ch) {
    const float predicted = c[ch] - (c[ch] - b[ch]) * (1.0f - a) * (1.0f - a);
    EXPECT_NEAR(p2[ch], predicted, 3.0f) << "channel " << ch;
  }
}

TEST_F(RenderTest, DeferredShadingLightsTheSideFacingTheLight) {
  // A 2 m billboard lit from +x with no ambient: its +x half is bright, its -x half dark.
  const glm::vec3 where(0.0f, 0.0f, 2.5f);
  ParticleState s = onePerFrame({where}, 1.0f);
  s.render.size = 2.0f;
  s.render.ambient = 0.0f;
  s.render.colorBirth = s.render.colorDeath = {0.8f, 0.8f, 0.8f};
  s.render.lightDirection = {1.0f, 0.0f, 0.0f};
  const Image lit = render(s, 1);
  const glm::ivec2 east = project(where + glm::vec3(0.6f, 0, 0)),
                   west = project(where - glm::vec3(0.6f, 0, 0));
  s.render.lightDirection = {-1.0f, 0.0f, 0.0f};
  const Image mirrored = render(s, 1);
  // The same pixel, the same alpha: only the light moved. Each half is brighter when lit.
  EXPECT_GT(int(lit.at(east.x, east.y).y), int(mirrored.at(east.x, east.y).y) + 20);
  EXPECT_GT(int(mirrored.at(west.x, west.y).y), int(lit.at(west.x, west.y).y) + 20);
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

// v = (0, 1 + x, 0): speeds 0 to 4 over x in [-1, 3], exactly 1 m/s at x = 0
// (linear, so the baked grid interpolates it exactly).
struct Shear final : AnalyticField {
  glm::vec3 evaluate(const glm::vec3& p) const override { return {0.0f, 1.0f + p.x, 0.0f}; }
};

// Particles born at (0, 0, 2) on the camera's axis, moving away from it at
// `speed` m/s (born with the field's velocity, so every one has it): they all
// cover the centre pixel, opaque, unlit.
ParticleState alongTheAxis(float speed, RenderMode mode) {
  ParticleState s = onePerFrame({{0.0f, 0.0f, 2.0f}}, 1.0f);
  s.emitters[0].velocity = {0.0f, speed, 0.0f};
  s.render.mode = mode;
  s.render.size = 0.6f;
  s.render.colorBy = ColorQuantity::Speed;
  s.render.colorMap = ColorMapName::Viridis;
  return s;
}

glm::vec3 centre(const Image& image) {
  const glm::ivec2 px = project({0.0f, 0.0f, 2.0f});
  return glm::vec3(glm::vec4(image.at(px.x, px.y))) / 255.0f;
}

glm::vec3 expected(ColorMapName map, float t) {
  return ColorMap::lookupTable(ColorMap(map).gpuTable(), t);
}

void expectNear(glm::vec3 got, glm::vec3 want, float tolerance, const std::string& what) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c] * 255.0f, want[c] * 255.0f, tolerance) << what << ", channel " << c;
}

TEST_F(RenderTest, AParticlesSpeedGetsTheColourTheMapGivesItInEveryMode) {
  auto field = std::make_shared<VectorField>(
      bake(Uniform({0.0f, 3.0f, 0.0f}), Box{{-5, -5, 0}, {5, 50, 5}}, {2, 2, 2}));
  for (const RenderMode mode : {RenderMode::Points, RenderMode::Billboards, RenderMode::Splat}) {
    ParticleState s = alongTheAxis(3.0f, mode);
    s.render.colorRange = ColorRange::Fixed;
    s.render.colorMin = 0.0f;
    s.render.colorMax = 4.0f;  // 3 m/s: t = 0.75
    // Points are drawn exactly; billboards and splats blend a few opaque
    // layers of the soft puff (1 - 0.0x of the background stays), and splats
    // carry t in 12 bits.
    const float tolerance = mode == RenderMode::Points ? 1.0f : 6.0f;
    expectNear(centre(render(s, 6, field)), expected(ColorMapName::Viridis, 0.75f), tolerance,
               "mode " + std::to_string(int(mode)));
    s.render.colorLog = true;
    s.render.colorMin = 0.3f;
    s.render.colorMax = 30.0f;  // log: 3 is halfway from 0.3 to 30
    expectNear(centre(render(s, 6, field)), expected(ColorMapName::Viridis, 0.5f), tolerance,
               "log, mode " + std::to_string(int(mode)));
  }
}

TEST_F(RenderTest, TheFieldsRangeSetsTheScaleByDefault) {
  // Speeds 0..4 over the field: 1 m/s is a quarter of the way.
  auto field =
      std::make_shared<VectorField>(bake(Shear(), Box{{-1, -5, 0}, {3, 50, 5}}, {5, 2, 2}));
  ParticleState s = alongTheAxis(1.0f, RenderMode::Points);
  s.render.colorMap = ColorMapName::CoolWarm;
  expectNear(centre(render(s, 6, field)), expected(ColorMapName::CoolWarm, 0.25f), 1.0f,
             "speed in the field's range");
  s.render.colorMap = ColorMapName::Fast;  // ParaView's default, its Lab path sampled
  expectNear(centre(render(s, 6, field)), expected(ColorMapName::Fast, 0.25f), 1.0f,
             "fast, speed in the field's range");
  s.render.colorBy = ColorQuantity::VelocityY;  // -> 0..4 as well
  s.render.colorMap = ColorMapName::Grey;
  expectNear(centre(render(s, 6, field)), glm::vec3(0.25f), 1.0f, "velocity y");
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

// The slice y = 0 through the shear field (speed 1 + x over x in [-1, 3]),
// facing the camera: each pixel has the map's colour of the speed there.
TEST_F(RenderTest, TheSliceShowsTheFieldsSpeedThroughTheColourMap) {
  auto field = std::make_shared<VectorField>(bake(Shear(), Box{{-1, -5, 0}, {3, 5, 5}}, {5, 2, 2}));
  ParticleState s = onePerFrame({}, 1.0f);
  s.render.colorBy = ColorQuantity::Speed;
  s.render.colorMap = ColorMapName::Plasma;
  s.slice.enabled = true;
  s.slice.origin = {0.0f, 0.0f, 2.0f};
  s.slice.normal = {0.0f, 1.0f, 0.0f};
  const Image image = render(s, 1, field);
  for (const float x : {-0.5f, 0.0f, 1.0f, 2.5f}) {
    const glm::ivec2 px = project({x, 0.0f, 2.0f});
    const glm::vec3 got = glm::vec3(glm::vec4(image.at(px.x, px.y))) / 255.0f;
    // Where that pixel's centre sees the plane y = 0, 8 m ahead of the camera.
    const float ndc = (float(px.x) + 0.5f) / float(kSize.x) * 2.0f - 1.0f;
    const float seen = ndc * 8.0f * std::tan(glm::radians(20.0f)) * float(kSize.x) / float(kSize.y);
    expectNear(got, expected(ColorMapName::Plasma, (1.0f + seen) / 4.0f), 1.5f,
               "x = " + std::to_string(seen));
  }
  // Off: the same pixels show the sky again.
  s.slice.enabled = false;
  const Image plain = render(s, 1, field);
  const glm::ivec2 px = project({1.0f, 0.0f, 2.0f});
  EXPECT_NE(plain.at(px.x, px.y), image.at(px.x, px.y));
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

struct Spin final : AnalyticField {  // solid-body rotation, 1 rad/s: vorticity 2
  glm::vec3 evaluate(const glm::vec3& p) const override { return {-p.y, p.x, 0.0f}; }
};

// Particles resting on the axis of a rotation whose strength is 2: the
// vorticity they feel is 4, half of the fixed range 0..8.
TEST_F(RenderTest, AParticleGetsTheColourOfTheVorticityItFeels) {
  auto field = std::make_shared<VectorField>(bake(Spin(), Box{{-5, -5, 0}, {5, 5, 5}}, {6, 6, 3}));
  for (const RenderMode mode : {RenderMode::Points, RenderMode::Splat}) {
    ParticleState s = alongTheAxis(0.0f, mode);
    s.sim.fieldStrength = 2.0f;
    s.render.colorBy = ColorQuantity::Vorticity;
    s.render.colorRange = ColorRange::Fixed;
    s.render.colorMin = 0.0f;
    s.render.colorMax = 8.0f;
    expectNear(centre(render(s, 4, field)), expected(ColorMapName::Viridis, 0.5f),
               mode == RenderMode::Points ? 1.0f : 6.0f, "mode " + std::to_string(int(mode)));
  }
}

// A file's scalar array colours the particles: temperature = 10 + 4 z on a
// grid whose z spacing makes the trilinear sample exact, so the particle at
// z = 2 feels 18, 0.4 of the way through the field's range 10..30.
TEST_F(RenderTest, AParticleGetsTheColourOfTheFileArrayItSits) {
  auto field = std::make_shared<VectorField>(
      bake(Uniform({0.0f, 0.0f, 0.0f}), Box{{-5, -5, 0}, {5, 5, 5}}, {2, 2, 6}));
  std::vector<float> pressure(field->pointCount(), 5.0f), temperature(field->pointCount());
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        temperature[field->index(i, j, k)] = 10.0f + 4.0f * float(k);
  field->addScalars("pressure", pressure);
  field->addScalars("temperature", temperature);
  for (const RenderMode mode : {RenderMode::Points, RenderMode::Splat}) {
    const float tolerance = mode == RenderMode::Points ? 1.0f : 6.0f;
    ParticleState s = alongTheAxis(0.0f, mode);
    s.render.colorBy = ColorQuantity::Array;
    s.render.colorArray = "temperature";
    expectNear(centre(render(s, 4, field)), expected(ColorMapName::Viridis, 0.4f), tolerance,
               "temperature, mode " + std::to_string(int(mode)));
    // No name: the field's first array, constant, so the scale's middle.
    s.render.colorArray.clear();
    expectNear(centre(render(s, 4, field)), expected(ColorMapName::Viridis, 0.5f), tolerance,
               "the first array, mode " + std::to_string(int(mode)));
  }
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

// render.order = sorted: two overlapping billboards on the camera's axis, the
// near one dark and the far one bright (a scalar array rising with depth,
// through viridis). Sorted, the near one covers the far one whatever order
// the particles were born in; unsorted, the one born last lands on top.
TEST_F(RenderTest, SortedBillboardsBlendBackToFrontWhateverTheirOrder) {
  auto field = std::make_shared<VectorField>(
      bake(Uniform({0.0f, 0.0f, 0.0f}), Box{{-5, -5, 0}, {5, 5, 5}}, {2, 2, 2}));
  std::vector<float> depth(field->pointCount());
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        depth[field->index(i, j, k)] = float(j);  // 0 at y = -5, 1 at y = +5
  field->addScalars("depth", depth);
  const glm::vec3 nearer(0.0f, -2.0f, 2.0f), farther(0.0f, 2.0f, 2.0f);
  for (const std::string backend : {"compute", "tf-gs"}) {
    SCOPED_TRACE(backend);
    auto image = [&](std::vector<glm::vec3> order, RenderOrder sorting) {
      ParticleState s = onePerFrame(order, 0.9f);
      s.render.colorBy = ColorQuantity::Array;
      s.render.colorMap = ColorMapName::Viridis;
      s.render.colorRange = ColorRange::Fixed;
      s.render.colorMin = 0.0f;
      s.render.colorMax = 1.0f;
      s.render.order = sorting;
      return centre(render(s, 1, field, backend));
    };
    const glm::vec3 nearFirst = image({nearer, farther}, RenderOrder::Sorted),
                    farFirst = image({farther, nearer}, RenderOrder::Sorted);
    expectNear(nearFirst, farFirst, 1.0f, "sorted: the order of birth does not matter");
    // The CPU's composite, back to front, of the two colours (t = 0.3 near,
    // 0.7 far) over the background b, with the billboards' alpha a at their
    // centres measured from one particle alone: near a + (far a + b (1 - a)) (1 - a).
    const glm::vec3 nearColor = expected(ColorMapName::Viridis, 0.3f),
                    farColor = expected(ColorMapName::Viridis, 0.7f);
    const glm::vec3 b = image({}, RenderOrder::Sorted),
                    alone = image({nearer}, RenderOrder::Sorted);
    const int ch = 2;  // blue: viridis at 0.3 is far from the background there
    const float a = (alone[ch] - b[ch]) / (nearColor[ch] - b[ch]);
    ASSERT_GT(a, 0.5f);
    ASSERT_LE(a, 1.0f);
    const glm::vec3 composite = nearColor * a + (farColor * a + b * (1.0f - a)) * (1.0f - a);
    expectNear(nearFirst, composite, 3.0f, "sorted against the CPU's composite");
    // Unsorted, the far particle drawn last covers the near one.
    expectNear(image({farther, nearer}, RenderOrder::Unsorted), farFirst, 1.0f,
               "unsorted, born far to near: already back to front");
    const glm::vec3 wrong = image({nearer, farther}, RenderOrder::Unsorted);
    EXPECT_GT(glm::length(wrong - nearFirst) * 255.0f, 20.0f) << "unsorted should show the far one";
  }
}

// A particle crossing the view in a wind leaves a trail where it was: drawn
// as GL lines with billboards and added to the sums with splats.
TEST_F(RenderTest, TrailsShowWhereTheParticleWasWithLinesAndWithSplats) {
  auto field = std::make_shared<VectorField>(
      bake(Uniform({1.0f, 0.0f, 0.0f}), Box{{-5, -5, 0}, {5, 50, 5}}, {2, 2, 2}));
  for (const RenderMode mode : {RenderMode::Billboards, RenderMode::Splat}) {
    ParticleState s = onePerFrame({{-2.0f, 0.0f, 2.06f}}, 1.0f);  // a row's middle, not its edge
    s.sim.maximum = 1000;
    s.emitters[0].velocity = {1.0f, 0.0f, 0.0f};
    s.render.mode = mode;
    s.render.size = 0.15f;
    const Image without = oneParticleAfter(s, field, 9);
    s.render.trailLength = 8;
    const Image with = oneParticleAfter(s, field, 9);
    // After 8 frames of 0.25 s the particle is at x = 0; its trail runs back to x = -1.75.
    int changed = 0;
    for (const float x : {-1.5f, -1.0f, -0.5f}) {
      const glm::ivec2 px = project({x, 0.0f, 2.06f});
      changed += redness(with.at(px.x, px.y)) > redness(without.at(px.x, px.y)) + 20.0f ? 1 : 0;
    }
    EXPECT_EQ(changed, 3) << "mode " << int(mode);
    // Ahead of the particle nothing changed.
    const glm::ivec2 ahead = project({1.5f, 0.0f, 2.06f});
    EXPECT_EQ(with.at(ahead.x, ahead.y), without.at(ahead.x, ahead.y)) << "mode " << int(mode);
  }
}
// Motion blur with a box shutter draws a particle convolved with its path
// over the shutter time: its opacity sums to the same, its centre moves back
// by half the path, and its spread along the path grows by the path's
// length squared over 12 (the variance of a uniform distribution).
TEST_F(RenderTest, MotionBlurSmearsAParticleOverItsPathInTheShutterTime) {
  const float speed = 4.0f, shutter = 0.25f;  // a 1 m path
  // Across the view, and slanted (a smear's rows are not its bounding box's).
  for (const glm::vec3 direction : {glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.6f, 0.0f, 0.8f)}) {
    auto field = std::make_shared<VectorField>(
        bake(Uniform(speed * direction), Box{{-5, -5, 0}, {5, 5, 5}}, {2, 2, 2}));
    const glm::vec3 at(0.0f, 0.0f, 2.0f);
    const glm::vec2 path = projectExactly(at) - projectExactly(at - direction);
    // Billboards smear; splats smear, or blur their images along their motion (the filter).
    for (const auto& look : {std::pair{RenderMode::Billboards, BlurMethod::Smear},
                             std::pair{RenderMode::Splat, BlurMethod::Smear},
                             std::pair{RenderMode::Splat, BlurMethod::Filter}}) {
      // Named copies: a lambda below uses them (it may not capture structured bindings).
      const RenderMode mode = look.first;
      const BlurMethod blur = look.second;
      SCOPED_TRACE(blur == BlurMethod::Filter ? "filter" : "smear");
      // Opacity from the green channel: the particle's is 0.1, the sky's near 0.8.
      const Image empty = render(onePerFrame({}, 0.8f), 1, field);
      struct Moments {
        double mass = 0;
        glm::dvec2 mean{0.0}, variance{0.0};
      };
      auto moments = [&](float shutterTime) {
        ParticleState s = onePerFrame({at}, 0.8f);
        s.emitters[0].velocity = speed * direction;  // born moving as the field moves it
        s.render.mode = mode;
        s.render.size = 0.6f;
        s.render.shutter = shutterTime;
        s.render.blur = blur;
        const Image image = render(s, 1, field);
        Moments m;
        glm::dvec2 sum(0.0), squares(0.0);
        for (int y = 0; y < kSize.y; ++y)
          for (int x = 0; x < kSize.x; ++x) {
            const double bg = empty.at(x, y).y, particle = 0.1 * 255.0;
            const double alpha = std::max(0.0, (bg - image.at(x, y).y) / (bg - particle));
            const glm::dvec2 p(x + 0.5, y + 0.5);
            m.mass += alpha;
            sum += alpha * p;
            squares += alpha * p * p;
          }
        m.mean = sum / m.mass;
        m.variance = squares / m.mass - m.mean * m.mean;
        return m;
      };
      const Moments still = moments(0.0f), blurred = moments(shutter);
      std::printf(
          "mode %d, blur %d, path (%.1f, %.1f) px: opacity %.2f -> %.2f, centre moved (%.2f, "
          "%.2f) px, variance up (%.2f, %.2f) px^2 (expected (%.2f, %.2f))\n",
          int(mode), int(blur), path.x, path.y, still.mass, blurred.mass,
          blurred.mean.x - still.mean.x, blurred.mean.y - still.mean.y,
          blurred.variance.x - still.variance.x, blurred.variance.y - still.variance.y,
          path.x * path.x / 12.0, path.y * path.y / 12.0);
      EXPECT_NEAR(blurred.mass, still.mass, 0.05 * still.mass);
      for (int axis = 0; axis < 2; ++axis) {
        const double expected = double(path[axis]) * path[axis] / 12.0;
        EXPECT_NEAR(blurred.mean[axis] - still.mean[axis], -0.5 * path[axis], 0.4) << axis;
        EXPECT_NEAR(blurred.variance[axis] - still.variance[axis], expected,
                    std::max(0.1 * expected, 0.3))
            << axis;
      }
    }
  }
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

// Molecules (MoleculeRenderer) are drawn into the particle buffers and lit by
// the same deferred pass: a dart's faces and a chain's ribbons cover the
// pixel of their centre in the colour the render attributes give; a ray
// through a closed dart meets one face that faces it (the back ones are
// culled), so opacity a lets a of the colour through, as "over" says.
TEST_F(RenderTest, MoleculesAreDrawnInTheParticlesColourAndOpacity) {
  const glm::vec3 where(0.5f, 0.0f, 2.2f);
  const auto molecules = [&](int complexity, float opacity) {
    ParticleState s = onePerFrame({where}, opacity);
    s.emitters[0].kind = EmitterKind::Molecules;
    s.molecules.complexity = complexity;
    s.molecules.size = 0.5f;
    s.molecules.width = 0.3f;
    return render(s, 1);
  };
  const Image empty = render(onePerFrame({}, 1.0f), 1);
  const glm::ivec2 px = project(where);
  const glm::vec3 colour = glm::vec3(0.9f, 0.1f, 0.1f) * 255.0f;
  for (int complexity : {4, 5}) {
    SCOPED_TRACE(complexity);
    const glm::u8vec4 c = molecules(complexity, 1.0f).at(px.x, px.y);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(float(c[k]), colour[k], 1.5f);
  }
  // Through a dart's face of opacity 0.5 (its back face culled).
  const glm::u8vec4 half = molecules(4, 0.5f).at(px.x, px.y), bg = empty.at(px.x, px.y);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(float(half[k]), 0.5f * colour[k] + 0.5f * float(bg[k]), 2.0f);
  // Nothing elsewhere: a corner of the image is the empty scene's.
  EXPECT_EQ(molecules(4, 1.0f).at(2, 2), empty.at(2, 2));
}

}  // namespace
}  // namespace sandstorm
