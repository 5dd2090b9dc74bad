// WindowSegments: a segment in view lands where glm::project puts its ends;
// one that passes behind the eye is cut at the near plane (window depth 0)
// and keeps its part in front; one wholly behind, or beyond the far plane,
// is gone. A box has twelve edges, each one unit along one axis.
#include "core/cave/window_segments.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace sandstorm {
namespace {

const glm::vec2 kSize(320.0f, 200.0f);

glm::mat4 viewProjection() {
  const glm::mat4 view = glm::lookAt(glm::vec3(0, -5, 1), glm::vec3(0, 0, 1), glm::vec3(0, 0, 1));
  return glm::perspective(glm::radians(60.0f), kSize.x / kSize.y, 0.1f, 50.0f) * view;
}

void expectNear(glm::vec3 got, glm::vec3 expected, float tolerance) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c], expected[c], c == 2 ? 1e-5f : tolerance) << "component " << c;
}

TEST(WindowSegments, ASegmentInViewLandsWhereItsEndsProject) {
  const std::array<std::array<glm::vec3, 2>, 1> world{
      {{glm::vec3(-1, 0, 0.5f), glm::vec3(2, 3, 2)}}};
  const auto got = windowSegments(viewProjection(), kSize, world);
  ASSERT_EQ(got.size(), 1u);
  const glm::mat4 view = glm::lookAt(glm::vec3(0, -5, 1), glm::vec3(0, 0, 1), glm::vec3(0, 0, 1));
  const glm::mat4 projection =
      glm::perspective(glm::radians(60.0f), kSize.x / kSize.y, 0.1f, 50.0f);
  const glm::vec4 viewport(0, 0, kSize.x, kSize.y);
  expectNear(got[0].a, glm::project(world[0][0], view, projection, viewport), 1e-3f);
  expectNear(got[0].b, glm::project(world[0][1], view, projection, viewport), 1e-3f);
}

TEST(WindowSegments, ASegmentPassingBehindTheEyeIsCutAtTheNearPlane) {
  // From in front of the eye (y = 0) to behind it (y = -10), along the line of sight's side.
  const std::array<std::array<glm::vec3, 2>, 1> world{{{glm::vec3(1, 0, 1), glm::vec3(1, -10, 1)}}};
  const auto got = windowSegments(viewProjection(), kSize, world);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_GT(got[0].a.z, 0.0f);
  EXPECT_NEAR(got[0].b.z, 0.0f, 1e-5f);  // its near end is on the near plane
  // That end is where the line meets the plane 0.1 m in front of the eye (y = -4.9).
  const glm::vec4 clip = viewProjection() * glm::vec4(1, -4.9f, 1, 1);
  EXPECT_NEAR(got[0].b.x, (clip.x / clip.w * 0.5f + 0.5f) * kSize.x, 0.05f);
  // Behind the eye altogether, or beyond the far plane: nothing.
  const std::array<std::array<glm::vec3, 2>, 2> hidden{
      {{glm::vec3(-1, -6, 1), glm::vec3(1, -8, 1)}, {glm::vec3(0, 60, 1), glm::vec3(1, 80, 2)}}};
  EXPECT_TRUE(windowSegments(viewProjection(), kSize, hidden).empty());
}

TEST(WindowSegments, ABoxHasTwelveUnitEdgesAlongItsAxes) {
  const glm::mat4 model =
      glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)), glm::vec3(2, 3, 4));
  int along[3] = {0, 0, 0};
  for (const auto& [a, b] : boxEdges(model)) {
    const glm::vec3 d = b - a;
    const int axis = d.x != 0.0f ? 0 : d.y != 0.0f ? 1 : 2;
    EXPECT_EQ(glm::length(d), axis == 0 ? 2.0f : axis == 1 ? 3.0f : 4.0f);
    ++along[axis];
    for (const glm::vec3& p : {a, b})
      for (int c = 0; c < 3; ++c)
        EXPECT_TRUE(p[c] == glm::vec3(1, 2, 3)[c] || p[c] == glm::vec3(3, 5, 7)[c]);
  }
  EXPECT_EQ(along[0], 4);
  EXPECT_EQ(along[1], 4);
  EXPECT_EQ(along[2], 4);
}

}  // namespace
}  // namespace sandstorm
