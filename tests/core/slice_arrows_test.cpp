// Slice arrows against flows worked out by hand: in a wind along the plane
// every arrow is parallel to it and equally long; a wind through the plane
// leaves no arrow; every arrow starts inside the slice.
#include "core/flow/slice_arrows.h"

#include <gtest/gtest.h>

#include "core/field/analytic_field.h"
#include "core/flow/slice_polygon.h"

namespace sandstorm {
namespace {

struct Wind final : AnalyticField {
  glm::vec3 w;
  explicit Wind(glm::vec3 v) : w(v) {}
  glm::vec3 evaluate(const glm::vec3&) const override { return w; }
};

TEST(SliceArrows, FollowTheFlowInThePlaneScaledToTheGrid) {
  const Box box{{-2, -2, 0}, {2, 2, 4}};
  const VectorField field = bake(Wind({1.0f, 0.5f, 2.0f}), box, {3, 3, 3});
  PhysicsInputs in;
  in.field = &field;
  const glm::vec3 normal(0, 1, 0);  // the plane y = 0: in-plane velocity (1, 0, 2)
  const auto polygon = slicePolygon(box, {}, {0, 0, 2}, normal);
  const auto arrows = sliceArrows(polygon, normal, 8, in);
  ASSERT_EQ(arrows.size(), 64u);  // the 4 x 4 m slice at 0.5 m spacing: 8 x 8 cells, all inside
  const glm::vec3 along = glm::normalize(glm::vec3(1, 0, 2));
  for (const SliceArrow& a : arrows) {
    EXPECT_NEAR(a.base.y, 0.0f, 1e-5f);
    EXPECT_TRUE(box.contains(a.base));
    const glm::vec3 shaft = a.tip - a.base;
    EXPECT_NEAR(glm::length(shaft), 0.9f * 0.5f, 1e-4f);  // all as fast as the fastest
    EXPECT_NEAR(glm::dot(glm::normalize(shaft), along), 1.0f, 1e-5f);
  }
  EXPECT_EQ(arrowLines(arrows, normal).size(), arrows.size() * 6);
  // A wind straight through the plane has no in-plane part: no arrows.
  const VectorField through = bake(Wind({0.0f, 3.0f, 0.0f}), box, {3, 3, 3});
  in.field = &through;
  EXPECT_TRUE(sliceArrows(polygon, normal, 8, in).empty());
}

}  // namespace
}  // namespace sandstorm
