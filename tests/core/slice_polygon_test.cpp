// slicePolygon against shapes worked out by hand.
#include "core/flow/slice_polygon.h"

#include <gtest/gtest.h>

namespace sandstorm {
namespace {

const Box kCube{{0, 0, 0}, {2, 2, 2}};

float area(const std::vector<glm::vec3>& polygon) {
  glm::vec3 sum(0.0f);
  for (std::size_t i = 0; i < polygon.size(); ++i)
    sum += glm::cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return 0.5f * glm::length(sum);
}

TEST(SlicePolygon, AnAxisAlignedSliceIsTheBoxsCrossSection) {
  const auto p = slicePolygon(kCube, {}, {1.0f, 0.5f, 1.0f}, {0, 1, 0});
  ASSERT_EQ(p.size(), 4u);
  for (const glm::vec3& c : p)
    EXPECT_FLOAT_EQ(c.y, 0.5f);
  EXPECT_NEAR(area(p), 4.0f, 1e-5f);
}

TEST(SlicePolygon, TheDiagonalSliceThroughACubesCentreIsAHexagon) {
  // Side 2: a regular hexagon of side sqrt(2), area 3 sqrt(3).
  const auto p = slicePolygon(kCube, {}, {1, 1, 1}, {1, 1, 1});
  ASSERT_EQ(p.size(), 6u);
  EXPECT_NEAR(area(p), 3.0f * std::sqrt(3.0f), 1e-4f);
  for (std::size_t i = 0; i < 6; ++i)  // in order around it: equal sides
    EXPECT_NEAR(glm::length(p[i] - p[(i + 1) % 6]), std::sqrt(2.0f), 1e-5f);
}

TEST(SlicePolygon, ACornerCutIsATriangleAndAMissIsNothing) {
  const auto corner = slicePolygon(kCube, {}, {0.5f, 0, 0}, {1, 1, 1});  // x + y + z = 0.5
  ASSERT_EQ(corner.size(), 3u);
  EXPECT_NEAR(area(corner), std::sqrt(3.0f) / 8.0f, 1e-5f);
  EXPECT_TRUE(slicePolygon(kCube, {}, {5, 5, 5}, {0, 0, 1}).empty());
  EXPECT_TRUE(slicePolygon(kCube, {}, {1, 1, 1}, {0, 0, 0}).empty());
}

TEST(SlicePolygon, APlacedFieldsSliceIsInTheParticlesCoordinates) {
  // Scaled by 3, turned a quarter about z, moved by (10, 0, 0): local x
  // becomes room y. The plane z = 4.5 in the room is z = 1.5 in the field.
  FieldPlacement placement;
  placement.offset = {10, 0, 0};
  placement.scale = 3.0f;
  placement.rotation = glm::mat3(0, 1, 0, -1, 0, 0, 0, 0, 1);
  const auto p = slicePolygon(kCube, placement, {0, 0, 4.5f}, {0, 0, 1});
  ASSERT_EQ(p.size(), 4u);
  EXPECT_NEAR(area(p), 36.0f, 1e-3f);
  for (const glm::vec3& c : p) {
    EXPECT_NEAR(c.z, 4.5f, 1e-5f);
    EXPECT_GE(c.y, -1e-4f);
    EXPECT_LE(c.y, 6.0001f);
    EXPECT_LE(c.x, 10.0001f);
    EXPECT_GE(c.x, 3.9999f);
  }
}

}  // namespace
}  // namespace sandstorm
