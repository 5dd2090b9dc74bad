// The OpenVDB grid walk against files OpenVDB writes itself, in every way it
// writes them (compression none, zip, active mask, blosc where built in; half
// floats; vec3s and vec3d; tiles at every level; one and two inactive values;
// instances; metadata of every type; affine and frustum transforms; empty
// grids): each walks to exactly the grid's end and loads. Damaged counts,
// strings, sizes and origins are refused before OpenVDB reads them, and a grid
// with any byte changed is either refused or read whole.
#include "core/io/vdb_file_check.h"

#include <gtest/gtest.h>

#include <openvdb/io/File.h>
#include <openvdb/math/Maps.h>

#include <random>

#include "core/io/field_loader.h"
#include "core/io/openvdb_grids.h"
#include "core/io/vdb_reader.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

constexpr std::size_t kBudget = std::size_t{1} << 30;

template <class Grid>
typename Grid::Ptr blockGrid(const std::string& name, int size = 20) {
  auto grid = Grid::create(typename Grid::ValueType(0.0));
  grid->setName(name);
  grid->setTransform(openvdb::math::Transform::createLinearTransform(0.25));
  auto acc = grid->getAccessor();
  for (auto it = openvdb::CoordBBox({-3, -2, -1}, {size, size / 2, size / 3}).begin(); it; ++it)
    acc.setValueOn(*it, typename Grid::ValueType(double((*it).x()), 0.5 * (*it).y(), 1.0));
  return grid;
}

std::filesystem::path write(const std::filesystem::path& path, const openvdb::GridPtrVec& grids,
                            std::uint32_t compression) {
  initializeOpenVdb();
  openvdb::io::File f(path.string());
  f.setCompression(compression);
  f.write(grids);
  f.close();
  return path;
}

void walkEvery(const std::filesystem::path& path) {
  const std::vector<VdbGridEntry> grids = checkVdbFile(path);
  for (std::size_t i = 0; i < grids.size(); ++i)
    if (grids[i].type.find("vec3") != std::string::npos) {
      SCOPED_TRACE(grids[i].name);
      EXPECT_NO_THROW(checkVdbGrid(path, grids, i, kBudget));
    }
}

struct Variant {
  const char* name;
  std::uint32_t compression;
  bool half;
};

class VdbGridCheck : public testing::TestWithParam<Variant> {};

TEST_P(VdbGridCheck, GridsOpenVdbWritesWalkToTheirEndAndLoad) {
  const auto dir = test::scratch();
  const Variant v = GetParam();
  auto s = blockGrid<openvdb::Vec3SGrid>("vel");
  auto d = blockGrid<openvdb::Vec3DGrid>("vel64", 30);
  for (auto g : {openvdb::GridBase::Ptr(s), openvdb::GridBase::Ptr(d)})
    g->setSaveFloatAsHalf(v.half);
  // Inactive voxels of two values beside the background: compression tag 5.
  auto acc = s->getAccessor();
  acc.setValueOff({0, 0, 0}, openvdb::Vec3s(7.0f));
  acc.setValueOff({1, 0, 0}, openvdb::Vec3s(-3.0f));
  // Tiles: an active 16^3 tile, an active 128^3 tile, and a root tile.
  s->fill(openvdb::CoordBBox({512, 512, 512}, {527, 527, 527}), openvdb::Vec3s(1.0f), true);
  s->fill(openvdb::CoordBBox({1024, 0, 0}, {1151, 127, 127}), openvdb::Vec3s(2.0f), true);
  s->tree().root().addTile(openvdb::Coord(8192, 0, 0), openvdb::Vec3s(3.0f), false);
  // Metadata of every fixed-size type, and a string.
  s->insertMeta("note", openvdb::StringMetadata("a note"));
  s->insertMeta("flag", openvdb::BoolMetadata(true));
  s->insertMeta("count", openvdb::Int32Metadata(7));
  s->insertMeta("big", openvdb::Int64Metadata(7));
  s->insertMeta("f", openvdb::FloatMetadata(1.5f));
  s->insertMeta("v", openvdb::Vec3DMetadata(openvdb::Vec3d(1, 2, 3)));
  s->insertMeta("m", openvdb::Mat4DMetadata(openvdb::Mat4d::identity()));
  d->setTransform(openvdb::math::Transform::createLinearTransform(
      openvdb::math::Mat4d(openvdb::math::rotation<openvdb::Mat4d>(openvdb::math::Y_AXIS, 0.3))));
  auto frustum = openvdb::Vec3SGrid::create();
  frustum->setName("frustum");
  frustum->setTransform(openvdb::math::Transform::createFrustumTransform(
      openvdb::BBoxd({0, 0, 0}, {10, 10, 10}), 0.5, 2.0, 0.1));
  frustum->getAccessor().setValueOn({1, 2, 3}, openvdb::Vec3s(1.0f));
  auto empty = openvdb::Vec3SGrid::create();
  empty->setName("empty");
  auto instance = s->copyGrid();  // shares the tree: written as an instance
  instance->setName("copy");
  const auto path =
      write(dir / (std::string(v.name) + ".vdb"), {s, d, frustum, empty, instance}, v.compression);
  walkEvery(path);
  LoadOptions options;
  options.arrayName = "vel";
  options.memoryBudget = std::size_t{4} << 30;
  options.resolution = {8, 8, 8};
  EXPECT_NO_THROW(loadField(path, options));
  options.arrayName = "copy";
  EXPECT_NO_THROW(loadField(path, options));
}

INSTANTIATE_TEST_SUITE_P(
    Written, VdbGridCheck,
    testing::Values(Variant{"none", openvdb::io::COMPRESS_NONE, false},
                    Variant{"zip", openvdb::io::COMPRESS_ZIP, false},
                    Variant{"mask", openvdb::io::COMPRESS_ACTIVE_MASK, false},
                    Variant{"zip_mask",
                            openvdb::io::COMPRESS_ZIP | openvdb::io::COMPRESS_ACTIVE_MASK, false},
                    Variant{"blosc_mask",
                            openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ACTIVE_MASK, false},
                    Variant{"half", openvdb::io::COMPRESS_ACTIVE_MASK, true},
                    Variant{"zip_half", openvdb::io::COMPRESS_ZIP, true}),
    [](const testing::TestParamInfo<Variant>& i) { return i.param.name; });

// Overwrites `n` bytes at `offset` of a file.
void patch(const std::filesystem::path& path, std::uint64_t offset, const void* bytes,
           std::size_t n) {
  std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
  f.seekp(std::streamoff(offset));
  f.write(static_cast<const char*>(bytes), std::streamsize(n));
}

std::string errorOf(const std::filesystem::path& path) {
  try {
    const auto grids = checkVdbFile(path);
    checkVdbGrid(path, grids, 0, kBudget);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// A single small grid, uncompressed, so byte positions are known.
std::filesystem::path plain(const std::filesystem::path& dir) {
  return write(dir / "plain.vdb", {blockGrid<openvdb::Vec3SGrid>("vel", 10)},
               openvdb::io::COMPRESS_NONE);
}

TEST(VdbGridCheckDamage, HugeMetadataCountsAndStringsAreRefused) {
  const auto dir = test::scratch();
  const auto path = plain(dir);
  const VdbGridEntry g = checkVdbFile(path).front();
  // The grid starts with its compression flags, then its metadata count.
  const std::uint32_t lots = 2000000000;
  patch(path, g.gridPos + 4, &lots, 4);
  EXPECT_NE(errorOf(path).find("2000000000 metadata entries cannot fit"), std::string::npos)
      << errorOf(path);
  const std::uint32_t one = 1, long_name = 1000000000;
  patch(path, g.gridPos + 4, &one, 4);
  patch(path, g.gridPos + 8, &long_name, 4);
  EXPECT_NE(errorOf(path).find("declares 1000000000 bytes"), std::string::npos) << errorOf(path);
}

TEST(VdbGridCheckDamage, RootCountsBeyondTheGridAreRefused) {
  const auto dir = test::scratch();
  const auto path = plain(dir);
  const VdbGridEntry g = checkVdbFile(path).front();
  // Find the root's counts: the buffer count (1) follows the transform; the
  // background (12 bytes) follows it, then the tile and child counts.
  std::string bytes = test::readAll(path);
  const std::string transform = "UniformScaleMap";
  std::size_t at = bytes.find(transform, g.gridPos);
  ASSERT_NE(at, std::string::npos);
  at += transform.size() + 120;  // the map's values
  std::int32_t buffers = 0;
  std::memcpy(&buffers, bytes.data() + at, 4);
  ASSERT_EQ(buffers, 1);
  const std::uint32_t lots = 3000000000u;
  patch(path, at + 4 + 12 + 4, &lots, 4);  // the child count
  EXPECT_NE(errorOf(path).find("3000000000 children cannot fit"), std::string::npos)
      << errorOf(path);
}

TEST(VdbGridCheckDamage, EveryChangedByteIsRefusedOrReadWhole) {
  const auto dir = test::scratch();
  const auto good = write(dir / "good.vdb", {blockGrid<openvdb::Vec3SGrid>("vel", 12)},
                          openvdb::io::COMPRESS_ZIP | openvdb::io::COMPRESS_ACTIVE_MASK);
  const std::string bytes = test::readAll(good);
  const VdbGridEntry g = checkVdbFile(good).front();
  std::mt19937 random(3);
  const auto bad = dir / "bad.vdb";
  int refused = 0, read = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::string b = bytes;
    const std::uint64_t at = g.gridPos + random() % (g.endPos - g.gridPos);
    b[at] = char(random());
    test::writeText(bad, b);
    LoadOptions options;
    options.memoryBudget = std::size_t{64} << 20;
    try {
      loadField(bad, options);
      ++read;
    } catch (const Error&) {
      ++refused;
    }
  }
  EXPECT_GT(refused, 0);
  EXPECT_EQ(refused + read, 300);
}

}  // namespace
}  // namespace sandstorm
