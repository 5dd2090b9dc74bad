// The seam between two CAVE walls, in pixels: a particle seen exactly through
// the shared edge of the front and left walls shows on the left edge of the
// front wall's image and the right edge of the left wall's image, at the same
// height in the room (the thesis's figure 6.1, checked by numbers).
#include <gtest/gtest.h>

#include "contexts/render/wall_renderer.h"
#include "core/sim/main_context.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

class SeamTest : public GlTest {};

constexpr int kSize = 96;

WallSpec wall(const char* name, WallCorners corners) {
  WallSpec w;
  w.name = name;
  w.corners = corners;
  w.offscreenSize = {kSize, kSize};
  return w;
}

// The image rows (top = 0) where the particle's colour touches the given column, averaged.
float rowAtColumn(const Image& image, int column) {
  float sum = 0, weight = 0;
  for (int y = 0; y < image.height; ++y) {
    const glm::u8vec4 c = image.at(column, y);
    const float red = float(c.x) - 0.5f * (float(c.y) + float(c.z));
    if (red > 60.0f) {
      sum += float(y) * red;
      weight += red;
    }
  }
  return weight > 0 ? sum / weight : -1.0f;
}

TEST_F(SeamTest, AParticleOnTheSharedEdgeMeetsItselfAcrossTheSeam) {
  const WallCorners front{{-1.5f, 1.5f, 0.0f}, {1.5f, 1.5f, 0.0f}, {-1.5f, 1.5f, 3.0f}};
  const WallCorners left{{-1.5f, -1.5f, 0.0f}, {-1.5f, 1.5f, 0.0f}, {-1.5f, -1.5f, 3.0f}};
  const glm::vec3 eye(0.2f, -0.3f, 1.6f);
  const glm::vec3 edgePoint(-1.5f, 1.5f, 2.2f);  // on the seam, 2.2 m up
  const glm::vec3 particle =
      eye + 1.8f * (edgePoint - eye);  // beyond it, on the same line of sight

  ParticleState s;
  s.emitters[0].shape = EmitterShape::Point;
  s.emitters[0].position = particle;
  s.emitters[0].rate = 4.0f;  // one per 0.25 s frame
  s.emitters[0].lifetime = 100.0f;
  s.sim.groundCollision = false;
  s.render.size = 0.15f;
  s.render.colorBirth = s.render.colorDeath = {0.95f, 0.05f, 0.05f};
  s.render.opacityBirth = s.render.opacityDeath = 1.0f;
  s.render.ambient = 1.0f;
  s.render.fieldBox = false;

  Image images[2];
  const WallCorners corners[2] = {front, left};
  for (int i = 0; i < 2; ++i) {
    MainContext::Options options;
    options.fixedDt = 0.25f;
    MainContext main(s, FieldUpdate{}, options);
    Viewer viewer;
    viewer.head.position = eye;
    main.setViewer(viewer);
    WallRenderer renderer(
        WallRendererSetup{.wall = wall(i == 0 ? "front" : "left", corners[i]),
                          .initial = s,
                          .terrain = std::make_shared<HeightMap>(HeightMap::flat(-10.0f)),
                          .capacity = 64});
    renderer.frame(main.next(), {0, 0});
    images[i] = renderer.capture();
    writePng(images[i],
             std::filesystem::temp_directory_path() /
                 (std::string("sandstorm-seam-") + (i == 0 ? "front" : "left") + ".png"));
  }
  // Front wall: the seam is its left column; left wall: its right column.
  const float onFront = rowAtColumn(images[0], 0);
  const float onLeft = rowAtColumn(images[1], kSize - 1);
  ASSERT_GE(onFront, 0.0f) << "the particle does not reach the front wall's left edge";
  ASSERT_GE(onLeft, 0.0f) << "the particle does not reach the left wall's right edge";
  EXPECT_NEAR(onFront, onLeft, 1.0f);  // the same height, to a pixel
  // And that height is the edge point's: 2.2 m of the 3 m wall, rows counted from the top.
  EXPECT_NEAR(onFront, (1.0f - 2.2f / 3.0f) * kSize - 0.5f, 1.5f);
  // Away from the seam neither image shows it.
  EXPECT_LT(rowAtColumn(images[0], kSize / 2), 0.0f);
  EXPECT_LT(rowAtColumn(images[1], kSize / 2), 0.0f);
}

}  // namespace
}  // namespace sandstorm
