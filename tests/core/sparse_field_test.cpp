#include "core/field/sparse_field.h"

#include <gtest/gtest.h>

#include "core/util/error.h"
#include "tests/core/sparse_grid_builder.h"

namespace sandstorm {
namespace {

// A linear field in index space over the voxels [0, 15]^3 (two leaves along
// each axis): trilinear interpolation reproduces it exactly.
glm::vec3 linear(glm::vec3 u) {
  return glm::vec3(1.0f + 0.5f * u.x, 2.0f - 0.25f * u.y, 0.125f * u.z);
}

std::vector<std::uint32_t> linearBlock(glm::vec3 background = glm::vec3(0.0f)) {
  return test::buildSparseGrid(
      [](const auto& set) {
        for (int k = 0; k < 16; ++k)
          for (int j = 0; j < 16; ++j)
            for (int i = 0; i < 16; ++i)
              set({i, j, k}, linear(glm::vec3(i, j, k)));
      },
      0.5, glm::dvec3(1.0, -2.0, 3.0), background);
}

TEST(SparseField, BoundsAndCountAreThoseOfTheActiveVoxels) {
  const SparseField f(linearBlock(), "block");
  EXPECT_EQ(f.activeVoxelCount(), 16u * 16u * 16u);
  EXPECT_EQ(f.indexMin(), glm::ivec3(0));
  EXPECT_EQ(f.indexMax(), glm::ivec3(15));
  EXPECT_EQ(f.voxelSize(), glm::vec3(0.5f));
  EXPECT_EQ(f.bounds().min, glm::vec3(1.0f, -2.0f, 3.0f));
  EXPECT_EQ(f.bounds().max, glm::vec3(8.5f, 5.5f, 10.5f));
  // Words of a NanoVDB grid: its size is its nodes, not its bounding box.
  EXPECT_LT(f.byteSize(), std::size_t(16) << 20);
}

TEST(SparseField, VoxelsReadTheirValuesAndTrilinearSamplingReproducesALinearField) {
  const SparseField f(linearBlock(), "block");
  EXPECT_EQ(f.voxel({3, 7, 11}), linear(glm::vec3(3, 7, 11)));
  EXPECT_TRUE(f.active({3, 7, 11}));
  EXPECT_FALSE(f.active({16, 7, 11}));
  for (const glm::vec3 u : {glm::vec3(0.0f), glm::vec3(3.25f, 7.5f, 11.75f),
                            glm::vec3(7.9f, 8.1f, 0.3f), glm::vec3(14.99f, 0.01f, 9.0f)}) {
    const glm::vec3 p = glm::vec3(1.0f, -2.0f, 3.0f) + 0.5f * u;
    const glm::vec3 want = linear(u), got = f.sample(p);
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(got[a], want[a], 1e-5f) << "at index " << u[a];
  }
}

TEST(SparseField, BeyondItsActiveVoxelsItReadsTheBackground) {
  const glm::vec3 background(0.5f, -1.0f, 2.0f);
  const SparseField f(linearBlock(background), "block");
  EXPECT_EQ(f.voxel({40, 0, 0}), background);
  // Three voxels beyond the last active one, and far away: the background.
  EXPECT_EQ(f.sample(glm::vec3(1.0f + 0.5f * 18.0f, 0.0f, 5.0f)), background);
  EXPECT_EQ(f.sample(glm::vec3(-1e9f, 1e9f, 5.0f)), background);
  // Half a voxel beyond the last active one along +x: halfway to the background.
  const glm::vec3 u(15.5f, 4.0f, 4.0f);
  const glm::vec3 want = 0.5f * (linear(glm::vec3(15.0f, 4.0f, 4.0f)) + background);
  const glm::vec3 got = f.sample(glm::vec3(1.0f, -2.0f, 3.0f) + 0.5f * u);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(got[a], want[a], 1e-5f);
}

TEST(SparseField, AFewVoxelsInAHugeBoxTakeTheMemoryOfTheirNodes) {
  // Two voxels 4000 apart along each axis: a dense grid of their box would
  // have 6.4e10 points.
  const SparseField f(test::buildSparseGrid([](const auto& set) {
                        set({0, 0, 0}, glm::vec3(1.0f));
                        set({4000, 4000, 4000}, glm::vec3(2.0f));
                      }),
                      "two");
  EXPECT_EQ(f.activeVoxelCount(), 2u);
  EXPECT_EQ(f.indexMax(), glm::ivec3(4000));
  EXPECT_LT(f.byteSize(), std::size_t(2) << 20);
  EXPECT_EQ(f.sample(glm::vec3(4000.0f)), glm::vec3(2.0f));
}

TEST(SparseField, TheOverviewSamplesTheFieldOnADenseGridOverItsBounds) {
  const SparseField f(linearBlock(), "block");
  const VectorField o = f.overview(4);
  EXPECT_EQ(o.dims(), glm::ivec3(4));
  EXPECT_EQ(o.bounds().min, f.bounds().min);
  EXPECT_EQ(o.bounds().max, f.bounds().max);
  EXPECT_EQ(o.at(1, 2, 3), f.sample(o.pointPosition(1, 2, 3)));
  EXPECT_EQ(f.overview(64).dims(), glm::ivec3(16));
}

std::string refusal(std::vector<std::uint32_t> words) {
  try {
    SparseField f(std::move(words), "bad.nvdb");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(SparseField, BuffersThatAreNotASoundVec3GridAreRefusedWithWhy) {
  const std::vector<std::uint32_t> good = linearBlock();
  EXPECT_NE(refusal({good.begin(), good.begin() + 100}).find("fewer than a grid's header"),
            std::string::npos);
  auto truncated = good;
  truncated.resize(good.size() / 2);
  EXPECT_NE(refusal(truncated).find("the buffer holds"), std::string::npos) << refusal(truncated);
  auto magic = good;
  magic[0] ^= 1u;
  EXPECT_NE(refusal(magic).find("magic"), std::string::npos);
  // The leaves' count raised past the buffer, and lowered so that the lower
  // nodes' children are not leaves.
  auto leaves = good;
  leaves[(672 + 32) / 4] = 1u << 30;
  EXPECT_NE(refusal(leaves).find("pass the grid's end"), std::string::npos) << refusal(leaves);
  auto fewer = good;
  fewer[(672 + 32) / 4] = 1;
  EXPECT_NE(refusal(fewer).find("not a node of the level below"), std::string::npos)
      << refusal(fewer);
  // A float grid.
  nanovdb::GridBuilder<float> builder(0.0f);
  builder.getAccessor().setValue(nanovdb::Coord(1, 2, 3), 1.0f);
  auto handle = builder.getHandle<>();
  std::vector<std::uint32_t> scalar(handle.size() / 4);
  std::memcpy(scalar.data(), handle.data(), handle.size());
  EXPECT_NE(refusal(scalar).find("expected Vec3f"), std::string::npos) << refusal(scalar);
  // Voxels past the index range sample()'s float arithmetic keeps exact.
  const std::string far = refusal(test::buildSparseGrid([](const auto& set) {
    set({1 << 25, 0, 0}, glm::vec3(1.0f));
  }));
  EXPECT_NE(far.find("expected within"), std::string::npos) << far;
  EXPECT_EQ(refusal(good), "");
}

}  // namespace
}  // namespace sandstorm
