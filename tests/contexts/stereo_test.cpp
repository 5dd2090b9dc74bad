// Stereo layouts against the mono images of each eye: side-by-side and
// top-bottom place each eye's image in its half, as one-eye walls draw it;
// anaglyph puts the left eye's luminance in red and the right eye's green and
// blue.
#include <gtest/gtest.h>

#include "contexts/render/wall_renderer.h"
#include "core/sim/main_context.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class StereoTest : public GlTest {};

const WallCorners kFront{{-1.5f, 1.5f, 0.0f}, {1.5f, 1.5f, 0.0f}, {-1.5f, 1.5f, 3.0f}};

Image renderWall(StereoMode mode, glm::ivec2 size, glm::vec3 head, float separation) {
  ParticleState s;
  s.emitters[0].shape = EmitterShape::Sphere;
  s.emitters[0].position = {0.3f, 3.0f, 1.6f};
  s.emitters[0].radius = 0.6f;
  s.emitters[0].rate = 2000.0f;
  s.emitters[0].lifetime = 100.0f;
  s.render.size = 0.1f;
  s.render.fieldBox = false;
  MainContext::Options options;
  options.fixedDt = 0.25f;
  MainContext main(s, FieldUpdate{}, options);
  Viewer viewer;
  viewer.head.position = head;
  viewer.head.right = {1, 0, 0};
  viewer.head.eyeSeparation = separation;
  main.setViewer(viewer);
  WallSpec wall;
  wall.name = "front";
  wall.corners = kFront;
  wall.stereo = mode;
  wall.offscreenSize = size;
  WallRenderer renderer(WallRendererSetup{.wall = wall, .initial = s, .capacity = 4096});
  renderer.frame(main.next(), {0, 0});
  return renderer.capture();
}

int maxDifference(const Image& a, int ax, int ay, const Image& b, int w, int h) {
  int worst = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(int(a.at(ax + x, ay + y)[c]) - int(b.at(x, y)[c])));
  return worst;
}

TEST_F(StereoTest, SideBySideAndTopBottomHoldEachEyesImage) {
  const glm::vec3 head(0.0f, 0.0f, 1.6f);
  const float sep = 0.2f;  // wide, so the eyes' images clearly differ
  const Image left = renderWall(StereoMode::Mono, {48, 64}, head - glm::vec3(sep / 2, 0, 0), 0.0f);
  const Image right = renderWall(StereoMode::Mono, {48, 64}, head + glm::vec3(sep / 2, 0, 0), 0.0f);
  ASSERT_GT(maxDifference(left, 0, 0, right, 48, 64), 30) << "the eyes see the same image";

  const Image sbs = renderWall(StereoMode::SideBySide, {96, 64}, head, sep);
  EXPECT_LE(maxDifference(sbs, 0, 0, left, 48, 64), 1);
  EXPECT_LE(maxDifference(sbs, 48, 0, right, 48, 64), 1);

  const Image leftWide =
      renderWall(StereoMode::Mono, {96, 32}, head - glm::vec3(sep / 2, 0, 0), 0.0f);
  const Image rightWide =
      renderWall(StereoMode::Mono, {96, 32}, head + glm::vec3(sep / 2, 0, 0), 0.0f);
  const Image tb = renderWall(StereoMode::TopBottom, {96, 64}, head, sep);
  EXPECT_LE(maxDifference(tb, 0, 0, leftWide, 96, 32), 1);  // left eye on top
  EXPECT_LE(maxDifference(tb, 0, 32, rightWide, 96, 32), 1);
}

// A passive-stereo projector pair (or a wall's eyes on two GPUs): each
// one-eye wall draws its half of the side-by-side wall, byte for byte.
TEST_F(StereoTest, OneEyeWallsDrawTheHalvesOfASideBySideWall) {
  const glm::vec3 head(0.0f, 0.0f, 1.6f);
  const float sep = 0.2f;
  const Image sbs = renderWall(StereoMode::SideBySide, {96, 64}, head, sep);
  const Image left = renderWall(StereoMode::LeftEye, {48, 64}, head, sep);
  const Image right = renderWall(StereoMode::RightEye, {48, 64}, head, sep);
  ASSERT_GT(maxDifference(left, 0, 0, right, 48, 64), 30) << "the eyes see the same image";
  EXPECT_EQ(maxDifference(sbs, 0, 0, left, 48, 64), 0);
  EXPECT_EQ(maxDifference(sbs, 48, 0, right, 48, 64), 0);
}

TEST_F(StereoTest, AnaglyphIsLeftLuminanceInRedAndRightInGreenAndBlue) {
  const glm::vec3 head(0.0f, 0.0f, 1.6f);
  const float sep = 0.2f;
  const Image left = renderWall(StereoMode::Mono, {64, 64}, head - glm::vec3(sep / 2, 0, 0), 0.0f);
  const Image right = renderWall(StereoMode::Mono, {64, 64}, head + glm::vec3(sep / 2, 0, 0), 0.0f);
  const Image ana = renderWall(StereoMode::Anaglyph, {64, 64}, head, sep);
  int worst = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const glm::vec3 l(left.at(x, y)), r(right.at(x, y)), a(ana.at(x, y));
      const float lum = 0.299f * l.x + 0.587f * l.y + 0.114f * l.z;
      worst = std::max(
          {worst, int(std::abs(a.x - lum)), int(std::abs(a.y - r.y)), int(std::abs(a.z - r.z))});
    }
  EXPECT_LE(worst, 2);
}

}  // namespace
}  // namespace sandstorm
