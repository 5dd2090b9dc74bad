// OpenVDB grids kept sparse (field.storage): NanoVDB's conversion of a grid
// OpenVDB wrote samples as OpenVDB's own BoxSampler does, within float
// rounding, at a transform with a different voxel size per axis; "auto" keeps
// sparse what is sparse and densifies what is dense; what cannot be kept
// sparse is refused saying why.
#include <gtest/gtest.h>

#include <random>
#include <regex>

#include <openvdb/io/File.h>
#include <openvdb/math/Maps.h>
#include <openvdb/tools/Interpolation.h>

#include "core/io/openvdb_grids.h"
#include "core/io/vdb_reader.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

void write(const std::filesystem::path& path, openvdb::GridPtrVec grids) {
  initializeOpenVdb();
  openvdb::io::File f(path.string());
  f.write(grids);
  f.close();
}

// A swirl in a ball of radius 12 voxels around two centres 300 voxels apart:
// 2 balls of ~7000 voxels in a box of 300^3.
template <class GridT>
typename GridT::Ptr twoBalls(openvdb::math::Transform::Ptr xform) {
  auto grid = GridT::create();
  grid->setTransform(xform);
  grid->setName("v");
  auto acc = grid->getAccessor();
  for (const openvdb::Coord c : {openvdb::Coord(0, 0, 0), openvdb::Coord(300, 280, 260)})
    for (int k = -12; k <= 12; ++k)
      for (int j = -12; j <= 12; ++j)
        for (int i = -12; i <= 12; ++i) {
          if (i * i + j * j + k * k > 144) continue;
          using V = typename GridT::ValueType;
          acc.setValueOn(c + openvdb::Coord(i, j, k),
                         V(-0.3 * j + 0.01 * i * k, 0.3 * i, 1.0 + 0.02 * k * k));
        }
  return grid;
}

openvdb::math::Transform::Ptr scaled() {
  return std::make_shared<openvdb::math::Transform>(
      std::make_shared<openvdb::math::ScaleTranslateMap>(openvdb::Vec3d(0.5, 0.25, 2.0),
                                                         openvdb::Vec3d(10.0, -3.0, 1.0)));
}

TEST(VdbSparse, SamplesAsOpenVdbsBoxSamplerWithinFloatRounding) {
  const auto dir = test::scratch();
  const auto grid = twoBalls<openvdb::Vec3SGrid>(scaled());
  const auto path = dir / "balls.vdb";
  write(path, {grid});
  LoadOptions options;
  options.sparse = SparseChoice::Always;
  LoadReport report;
  const std::optional<SparseField> f = readSparseVdb(path, options, report);
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(f->activeVoxelCount(), grid->activeVoxelCount());
  EXPECT_EQ(f->indexMin(), glm::ivec3(-12));
  EXPECT_EQ(f->indexMax(), glm::ivec3(312, 292, 272));
  EXPECT_EQ(f->voxelSize(), glm::vec3(0.5f, 0.25f, 2.0f));
  EXPECT_EQ(f->bounds().min, glm::vec3(10.0f - 6.0f, -3.0f - 3.0f, 1.0f - 24.0f));
  // A dense grid of the box would take 12 * 325 * 305 * 285 bytes (340 MB).
  EXPECT_LT(f->byteSize(), std::size_t(24) << 20);
  EXPECT_EQ(report.arrayName, "v");

  auto acc = grid->getConstAccessor();
  openvdb::tools::GridSampler<decltype(acc), openvdb::tools::BoxSampler> box(acc,
                                                                             grid->transform());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> near(-14.0, 14.0);
  double worst = 0.0;
  int inside = 0;
  for (int n = 0; n < 20000; ++n) {
    // Around either ball, and across its edge into the background.
    const openvdb::Vec3d centre = n % 2 ? openvdb::Vec3d(300, 280, 260) : openvdb::Vec3d(0.0);
    const openvdb::Vec3d ijk = centre + openvdb::Vec3d(near(rng), near(rng), near(rng));
    const openvdb::Vec3d world = grid->transform().indexToWorld(ijk);
    const openvdb::Vec3s want = box.wsSample(world);
    const glm::vec3 got = f->sample(glm::vec3(world.x(), world.y(), world.z()));
    inside += want.length() > 0.0f;
    for (int a = 0; a < 3; ++a)
      worst = std::max(worst, std::abs(double(got[a]) - double(want[a])));
  }
  std::printf("sparse sample vs OpenVDB BoxSampler: max |difference| = %.3g\n", worst);
  // Positions in floats at up to 166 m are rounded by up to 1e-5 m, 6e-5
  // voxels along the 0.25 m axis, where the swirl changes by up to ~0.6 a
  // voxel: up to 4e-5 from the position alone, then the weights' rounding.
  EXPECT_LT(worst, 1e-4);
  EXPECT_GT(inside, 5000);
}

TEST(VdbSparse, DoubleGridsAreRoundedToFloatsOnce) {
  const auto dir = test::scratch();
  const auto grid = twoBalls<openvdb::Vec3DGrid>(scaled());
  const auto path = dir / "double.vdb";
  write(path, {grid});
  LoadOptions options;
  options.sparse = SparseChoice::Always;
  LoadReport report;
  const auto f = readSparseVdb(path, options, report);
  ASSERT_TRUE(f.has_value());
  const openvdb::Vec3d v = grid->tree().getValue(openvdb::Coord(3, -4, 5));
  EXPECT_EQ(f->voxel({3, -4, 5}), glm::vec3(float(v.x()), float(v.y()), float(v.z())));
}

TEST(VdbSparse, AutoKeepsSparseGridsSparseAndDenseOnesDense) {
  const auto dir = test::scratch();
  write(dir / "balls.vdb", {twoBalls<openvdb::Vec3SGrid>(scaled())});
  auto block = openvdb::Vec3SGrid::create();
  block->setName("v");
  block->tree().fill(openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(19)),
                     openvdb::Vec3s(1, 0, 0), true);
  write(dir / "block.vdb", {block});
  LoadOptions options;
  options.sparse = SparseChoice::Auto;
  LoadReport report;
  EXPECT_TRUE(readSparseVdb(dir / "balls.vdb", options, report).has_value());
  EXPECT_FALSE(readSparseVdb(dir / "block.vdb", options, report).has_value());
  options.sparse = SparseChoice::Never;
  EXPECT_FALSE(readSparseVdb(dir / "balls.vdb", options, report).has_value());
}

TEST(VdbSparse, WhatCannotBeKeptSparseIsRefusedSayingWhy) {
  const auto dir = test::scratch();
  auto rotated = openvdb::math::Transform::createLinearTransform(0.5);
  rotated->postRotate(0.3, openvdb::math::Z_AXIS);
  write(dir / "rotated.vdb", {twoBalls<openvdb::Vec3SGrid>(rotated)});
  auto staggered = twoBalls<openvdb::Vec3SGrid>(scaled());
  staggered->setGridClass(openvdb::GRID_STAGGERED);
  write(dir / "mac.vdb", {staggered});
  write(dir / "balls.vdb", {twoBalls<openvdb::Vec3SGrid>(scaled())});
  LoadOptions options;
  options.sparse = SparseChoice::Always;
  LoadReport report;
  test::expectError([&] { readSparseVdb(dir / "rotated.vdb", options, report); },
                    {"rotated.vdb", "rotated", "field.storage = \"dense\""});
  test::expectError([&] { readSparseVdb(dir / "mac.vdb", options, report); },
                    {"mac.vdb", "staggered"});
  LoadOptions resampled = options;
  resampled.resolution = {32, 32, 32};
  test::expectError([&] { readSparseVdb(dir / "balls.vdb", resampled, report); },
                    {"balls.vdb", "field.resolution"});
  LoadOptions tight = options;
  tight.memoryBudget = std::size_t(1) << 20;
  test::expectError([&] { readSparseVdb(dir / "balls.vdb", tight, report); },
                    {"balls.vdb", "field.memory_budget"});
  // "auto" densifies what cannot be sparse instead of failing.
  options.sparse = SparseChoice::Auto;
  EXPECT_FALSE(readSparseVdb(dir / "rotated.vdb", options, report).has_value());
  EXPECT_FALSE(readSparseVdb(dir / "mac.vdb", options, report).has_value());
}

// A grid asked for dense whose dense copy passes the budget: the error names
// each way that fits (a coarser field.resolution, a larger budget, keeping
// it sparse), and taking the resolution or the sparse storage it names opens it.
TEST(VdbSparse, ADenseCopyOverTheBudgetNamesEachWayThatFits) {
  const auto dir = test::scratch();
  write(dir / "balls.vdb", {twoBalls<openvdb::Vec3SGrid>(scaled())});
  LoadOptions options;                          // dense (SparseChoice::Never)
  options.memoryBudget = std::size_t(8) << 20;  // the box's dense copy: 340 MB
  LoadReport report;
  std::string what;
  try {
    readVdb(dir / "balls.vdb", options, report);
  } catch (const Error& e) {
    what = e.what();
  }
  std::smatch m;
  ASSERT_TRUE(
      std::regex_search(what, m, std::regex(R"(field.resolution = \[(\d+), (\d+), (\d+)\])")))
      << what;
  EXPECT_NE(what.find("raise field.memory_budget to at least"), std::string::npos) << what;
  EXPECT_NE(what.find("field.storage = \"sparse\""), std::string::npos) << what;
  LoadOptions coarser = options;
  coarser.resolution = {std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3])};
  EXPECT_EQ(readVdb(dir / "balls.vdb", coarser, report).dims(), coarser.resolution);
  LoadOptions sparse = options;
  sparse.sparse = SparseChoice::Always;
  EXPECT_TRUE(readSparseVdb(dir / "balls.vdb", sparse, report).has_value());
}

}  // namespace
}  // namespace sandstorm
