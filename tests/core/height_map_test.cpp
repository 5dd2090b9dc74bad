#include "core/field/height_map.h"

#include <gtest/gtest.h>

#include "core/util/error.h"

namespace sandstorm {
namespace {

TEST(HeightMap, BilinearIsExactForPlanes) {
  // h = 0.5 x - 0.25 y + 1 on a 4 x 3 grid over [0, 3] x [0, 2].
  std::vector<float> h;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i)
      h.push_back(0.5f * i - 0.25f * j + 1.0f);
  const HeightMap map({0, 0}, {3, 2}, {4, 3}, h);
  EXPECT_NEAR(map.heightAt({1.3f, 0.7f}), 0.5f * 1.3f - 0.25f * 0.7f + 1.0f, 1e-6f);
  EXPECT_NEAR(map.heightAt({-5.0f, 0.0f}), 1.0f, 1e-6f);  // clamped to the edge
  const glm::vec3 n = map.normalAt({1.5f, 1.0f});
  EXPECT_NEAR(n.x / n.z, -0.5f, 1e-5f);
  EXPECT_NEAR(n.y / n.z, 0.25f, 1e-5f);
}

TEST(HeightMap, RejectsBadGrids) {
  EXPECT_THROW(HeightMap({0, 0}, {1, 1}, {1, 2}, {0, 0}), Error);
  EXPECT_THROW(HeightMap({0, 0}, {1, 1}, {2, 2}, {0, 0, 0}), Error);
  EXPECT_THROW(HeightMap({0, 0}, {0, 1}, {2, 2}, {0, 0, 0, 0}), Error);
}

}  // namespace
}  // namespace sandstorm
