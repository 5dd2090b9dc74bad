// The passes that replace raster fills on offscreen walls draw what the
// raster ones draw. SceneBackground draws a flat ground and the sky by compute, after the
// raster items; a height map's terrain stays raster. The two must draw the
// same scene: here a flat ground against a height map that is flat but for
// a millimetre at a corner 14 km away (so it takes the raster path), with a
// ball of particles and an obstacle half sunk into the ground (the ground
// must hide their lower halves: the particles by the scene depth the pass
// writes, the obstacle by the depth compare) and, with billboards, trails
// (translucent, drawn after the pass, hidden behind the ground by hand).
// The field's box is drawn by the pass too: its lines lie on the box's edges
// as glm::project puts them, and the ground hides the part below it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include <glm/gtc/matrix_transform.hpp>

#include <epoxy/gl.h>

#include "contexts/particles/particle_post.h"
#include "contexts/particles/particle_system.h"
#include "contexts/render/view_renderer.h"
#include "contexts/render/wall_renderer.h"
#include "core/cave/view.h"
#include "core/cave/window_segments.h"
#include "core/sim/main_context.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class SceneBackgroundTest : public GlTest {};

constexpr glm::ivec2 kSize{160, 120};

ParticleState sunkCloud(RenderMode mode) {
  ParticleState s;
  s.sim.maximum = 3000;
  s.sim.groundCollision = false;
  Emitter& e = s.emitters[0];
  e.shape = EmitterShape::Sphere;
  e.position = {0.8f, 0.0f, 0.2f};
  e.radius = 1.2f;
  e.rate = 2500.0f / 0.25f;  // everything in the first frame
  e.lifetime = 3.0f;
  e.lifetimeVariance = 0.0f;
  e.velocity = {0.0f, 0.0f, 0.4f};
  s.render.mode = mode;
  s.render.size = 0.2f;
  s.render.trailLength = mode == RenderMode::Billboards ? 8 : 0;
  Obstacle ball;
  ball.position = {-1.6f, 0.5f, 0.0f};
  ball.radius = 0.7f;
  ball.flow = false;
  s.obstacles.push_back(ball);
  return s;
}

Image render(const ParticleState& state, std::shared_ptr<HeightMap> terrain) {
  MainContext::Options options;
  options.fixedDt = 0.25f;
  options.seed = 5;
  MainContext main(state, FieldUpdate{}, options);
  WallSpec wall;
  wall.name = "test";
  wall.camera = CameraSpec{{0.0f, -7.0f, 1.6f}, {0.0f, 0.0f, 0.4f}, 50.0f};
  wall.offscreenSize = kSize;
  WallRenderer renderer(WallRendererSetup{.wall = wall,
                                          .initial = state,
                                          .terrain = std::move(terrain),
                                          .capacity = 4096,
                                          .backend = "compute",
                                          .nearPlane = 0.1f,
                                          .farPlane = 200.0f});
  for (int f = 0; f < 4; ++f) {
    FramePacket p = main.next();
    if (f > 0) p.emission.assign(p.emission.size(), 0u);
    renderer.frame(p, {0, 0});
  }
  return renderer.capture();
}

TEST_F(SceneBackgroundTest, TheFlatGroundAndSkyByComputeMatchTheRasterTerrain) {
  const auto flat = std::make_shared<HeightMap>(HeightMap::flat(0.0f));
  ASSERT_TRUE(flat->isFlat());
  const auto raster = std::make_shared<HeightMap>(glm::vec2(-1e4f), glm::vec2(1e4f), glm::ivec2(2),
                                                  std::vector<float>{0, 0, 0, 1e-3f});
  ASSERT_FALSE(raster->isFlat());
  for (RenderMode mode : {RenderMode::Billboards, RenderMode::Splat}) {
    SCOPED_TRACE(mode == RenderMode::Billboards ? "billboards and trails" : "splats");
    const ParticleState state = sunkCloud(mode);
    const Image a = render(state, flat), b = render(state, raster);
    ParticleState empty = state;
    empty.emitters[0].rate = 0.0f;
    empty.obstacles.clear();
    const Image scene = render(empty, flat);
    double mean = 0.0, over16 = 0.0, shows = 0.0;
    const int pixels = kSize.x * kSize.y;
    for (int i = 0; i < pixels; ++i) {
      int worst = 0, changed = 0;
      for (int c = 0; c < 3; ++c) {
        const std::size_t k = std::size_t(i) * 4 + std::size_t(c);
        const int d = std::abs(int(a.rgba[k]) - int(b.rgba[k]));
        mean += d;
        worst = std::max(worst, d);
        changed = std::max(changed, std::abs(int(a.rgba[k]) - int(scene.rgba[k])));
      }
      if (worst > 16) over16 += 1;
      if (changed > 8) shows += 1;
    }
    mean /= 3.0 * pixels;
    std::printf(
        "|compute - raster| mean %.3f/255, %.2f%% of pixels off by > 16; the particles "
        "and ball change %.1f%% of the image\n",
        mean, 100.0 * over16 / pixels, 100.0 * shows / pixels);
    if (const char* dir = std::getenv("SANDSTORM_TEST_IMAGES")) {
      const std::string tag = mode == RenderMode::Billboards ? "billboards" : "splats";
      writePng(a, std::string(dir) + "/background-compute-" + tag + ".png");
      writePng(b, std::string(dir) + "/background-raster-" + tag + ".png");
    }
    EXPECT_GT(shows / pixels, 0.05);  // the scene shows its items
    // The sky and ground themselves: every pixel of the empty scene is sky
    // or ground (not the clear colour), both above and below the horizon.
    EXPECT_NE(scene.rgba[0], 0);
    EXPECT_NE(scene.rgba[std::size_t(pixels - 1) * 4], 0);
    EXPECT_LT(mean, 0.5);
    EXPECT_LT(over16 / pixels, 0.005);
  }
}

// ParticlePost composites by compute into an offscreen wall's RGBA8 image
// and by a full-screen triangle elsewhere (a window; here a renderbuffer):
// the same pixels, within the 8-bit rounding, at the view's place in a
// destination twice as wide (side-by-side stereo's right eye).
TEST_F(SceneBackgroundTest, TheComputeCompositeMatchesTheRasterOne) {
  const ParticleState state = sunkCloud(RenderMode::Splat);
  MainContext::Options options;
  options.fixedDt = 0.25f;
  MainContext main(state, FieldUpdate{}, options);
  ParticleSystem system(state, {.capacity = 4096});
  system.advance(main.next());
  const View view =
      perspectiveView({0.0f, -7.0f, 1.6f}, {0.0f, 0.0f, 0.4f}, {0, 0, 1}, glm::radians(50.0f),
                      float(kSize.x) / float(kSize.y), 0.1f, 200.0f);
  ViewRenderer renderer;
  renderer.drawScene(system, view, kSize);
  system.renderParticles(renderer.targets(), &view);

  const glm::ivec2 wide(2 * kSize.x, kSize.y);
  OutputTarget image;  // an RGBA8 texture: the compute pass
  image.resize(wide);
  gl::Renderbuffer color = gl::createRenderbuffer();  // the raster pass
  glNamedRenderbufferStorage(color.id(), GL_RGBA8, wide.x, wide.y);
  gl::Framebuffer window = gl::createFramebuffer();
  glNamedFramebufferRenderbuffer(window.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color.id());
  ASSERT_TRUE(ParticlePost::computes(image.framebuffer()));
  ASSERT_FALSE(ParticlePost::computes(window.id()));
  ASSERT_FALSE(ParticlePost::computes(0));
  for (GLuint fbo : {image.framebuffer(), window.id()}) {
    // 128/255, not 0.5: 127.5 rounds to 127 on NVIDIA and to 128 on llvmpipe.
    const float grey[4] = {128.0f / 255.0f, 128.0f / 255.0f, 128.0f / 255.0f, 1.0f};
    glClearNamedFramebufferfv(fbo, GL_COLOR, 0, grey);
    system.composite(renderer.targets(), fbo, {kSize.x, 0});
  }
  const Image a = readFramebuffer(image.framebuffer(), GL_COLOR_ATTACHMENT0, wide);
  const Image b = readFramebuffer(window.id(), GL_COLOR_ATTACHMENT0, wide);
  int largest = 0, changed = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    largest = std::max(largest, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
    if (i % 4 != 3 && a.rgba[i] != 128) ++changed;
  }
  EXPECT_LE(largest, 1);
  // The left half keeps the clear colour; the right half holds the view.
  EXPECT_EQ(a.rgba[0], 128);
  EXPECT_GT(changed, kSize.x * kSize.y);
}

// The field's box: one-pixel lines of the box colour on the edges'
// projections; the part below the ground (z < 0) hidden by it.
TEST_F(SceneBackgroundTest, TheFieldsBoxLiesOnItsProjectedEdgesAndTheGroundHidesWhatIsBelow) {
  const Box bounds{{-1.5f, -1.0f, -0.8f}, {1.5f, 1.0f, 1.6f}};
  ParticleState s;
  s.emitters[0].rate = 0.0f;  // no particles: the scene alone
  s.render.fieldBox = true;
  MainContext::Options options;
  options.fixedDt = 0.25f;
  auto field = std::make_shared<VectorField>(bounds, glm::ivec3(2));
  MainContext main(s, FieldUpdate{.field = field}, options);
  WallSpec wall;
  wall.name = "box";
  const glm::vec3 eye(2.5f, -6.0f, 2.4f), target(0.0f, 0.0f, 0.3f);
  wall.camera = CameraSpec{eye, target, 50.0f};
  wall.offscreenSize = kSize;
  WallRenderer renderer(WallRendererSetup{
      .wall = wall, .initial = s, .capacity = 4096, .nearPlane = 0.1f, .farPlane = 200.0f});
  renderer.frame(main.next(), {0, 0});
  const Image image = renderer.capture();

  const View v = perspectiveView(eye, target, {0, 0, 1}, glm::radians(50.0f),
                                 float(kSize.x) / float(kSize.y), 0.1f, 200.0f);
  const glm::vec4 viewport(0, 0, kSize.x, kSize.y);
  const auto isLine = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= kSize.x || y >= kSize.y) return false;
    const glm::u8vec4 c = image.at(x, y);
    return std::abs(int(c.x) - 64) <= 2 && std::abs(int(c.y) - 64) <= 2 &&
           std::abs(int(c.z) - 77) <= 2;
  };
  // Whether a line pixel lies within one pixel of window position w (y up).
  const auto lineNear = [&](glm::vec3 w) {
    const int x = int(std::floor(w.x)), y = kSize.y - 1 - int(std::floor(w.y));
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (isLine(x + dx, y + dy)) return true;
    return false;
  };
  const glm::mat4 model = glm::scale(glm::translate(glm::mat4(1.0f), bounds.min), bounds.extent());
  // Where the edges above the ground project (densely), to leave out the
  // points below it that project next to them.
  std::vector<glm::vec2> visible;
  for (const auto& [a, b] : boxEdges(model))
    for (int i = 0; i <= 400; ++i)
      if (const glm::vec3 p = glm::mix(a, b, float(i) / 400.0f); p.z >= 0.0f)
        visible.emplace_back(glm::project(p, v.view, v.projection, viewport));
  const auto nextToVisible = [&](glm::vec2 w) {
    return std::any_of(visible.begin(), visible.end(),
                       [&](glm::vec2 q) { return glm::length(q - w) < 3.0f; });
  };
  int above = 0, shown = 0, below = 0, hidden = 0;
  for (const auto& [a, b] : boxEdges(model))
    for (int i = 1; i < 40; ++i) {
      const glm::vec3 p = glm::mix(a, b, float(i) / 40.0f);
      const glm::vec3 w = glm::project(p, v.view, v.projection, viewport);
      if (w.x < 2 || w.y < 2 || w.x > kSize.x - 2 || w.y > kSize.y - 2) continue;
      if (p.z > 0.05f) {
        ++above;
        if (lineNear(w)) ++shown;
      } else if (p.z < -0.05f && !nextToVisible(w)) {
        ++below;
        if (!lineNear(w)) ++hidden;
      }
    }
  std::printf("%d of %d points above the ground on a line, %d of %d below hidden\n", shown, above,
              hidden, below);
  EXPECT_GT(above, 150);
  EXPECT_EQ(shown, above);
  EXPECT_GT(below, 20);
  EXPECT_EQ(hidden, below);
  // No line colour more than two pixels from every edge's projection.
  int stray = 0;
  for (int y = 0; y < kSize.y; ++y)
    for (int x = 0; x < kSize.x; ++x) {
      if (!isLine(x, y)) continue;
      const glm::vec2 c(float(x) + 0.5f, float(kSize.y - y) - 0.5f);
      bool near = false;
      for (const auto& [a, b] : boxEdges(model)) {
        const glm::vec2 pa(glm::project(a, v.view, v.projection, viewport)),
            pb(glm::project(b, v.view, v.projection, viewport));
        const glm::vec2 d = pb - pa;
        const float t = glm::clamp(glm::dot(c - pa, d) / glm::dot(d, d), 0.0f, 1.0f);
        near = near || glm::length(c - (pa + t * d)) <= 2.0f;
      }
      if (!near) ++stray;
    }
  EXPECT_EQ(stray, 0);
}

}  // namespace
}  // namespace sandstorm
