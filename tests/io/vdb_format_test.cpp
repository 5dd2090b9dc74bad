// OpenVDB files written by OpenVDB itself load with the right values, bounds
// and orientation, transforms and staggering honoured; ours read back through
// openvdb::io::File unchanged.
#include <gtest/gtest.h>

#include <cmath>

#include <openvdb/io/File.h>
#include <openvdb/math/Maps.h>

#include "core/io/field_loader.h"
#include "core/io/field_writer.h"
#include "core/io/openvdb_grids.h"
#include "core/io/vdb_reader.h"
#include "core/io/vdb_writer.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

using test::asymmetric;

openvdb::Vec3s toVdb(const glm::dvec3& v) {
  return openvdb::Vec3s(float(v.x), float(v.y), float(v.z));
}

// A Vec3 grid holding the asymmetric field at each voxel's world position.
openvdb::Vec3SGrid::Ptr asymmetricGrid(openvdb::math::Transform::Ptr xform, openvdb::CoordBBox box,
                                       const std::string& name = "vel") {
  auto grid = openvdb::Vec3SGrid::create();
  grid->setTransform(xform);
  grid->setName(name);
  auto acc = grid->getAccessor();
  for (auto it = box.begin(); it; ++it) {
    const openvdb::Vec3d w = xform->indexToWorld(*it);
    acc.setValueOn(*it, toVdb(asymmetric({w.x(), w.y(), w.z()})));
  }
  return grid;
}

void write(const std::filesystem::path& path, openvdb::GridPtrVec grids) {
  initializeOpenVdb();
  openvdb::io::File f(path.string());
  f.write(grids);
  f.close();
}

void expectAsymmetricAt(const VectorField& f, float tolerance, int margin = 0) {
  for (int k = margin; k < f.dims().z - margin; ++k)
    for (int j = margin; j < f.dims().y - margin; ++j)
      for (int i = margin; i < f.dims().x - margin; ++i) {
        const glm::vec3 expected(asymmetric(glm::dvec3(f.pointPosition(i, j, k))));
        ASSERT_NEAR(glm::length(f.at(i, j, k) - expected), 0.0f, tolerance)
            << "at point " << i << " " << j << " " << k;
      }
}

TEST(VdbFormat, GridWrittenByOpenVdbLoadsWithItsTransform) {
  initializeOpenVdb();
  const auto dir = test::scratch();
  auto map = std::make_shared<openvdb::math::ScaleTranslateMap>(openvdb::Vec3d(0.5, 0.25, 2.0),
                                                                openvdb::Vec3d(10.0, -3.0, 1.0));
  auto xform = std::make_shared<openvdb::math::Transform>(map);
  const openvdb::CoordBBox box(openvdb::Coord(-2, 1, 0), openvdb::Coord(3, 4, 2));
  auto density = openvdb::FloatGrid::create();
  density->setName("density");
  density->tree().setValueOn(openvdb::Coord(0, 0, 0), 1.0f);
  const auto path = dir / "openvdb.vdb";
  write(path, {density, asymmetricGrid(xform, box)});

  LoadReport report;
  const VectorField f = loadField(path, {}, &report);
  EXPECT_EQ(report.arrayName, "vel");
  EXPECT_EQ(f.dims(), glm::ivec3(6, 4, 3));
  EXPECT_EQ(f.bounds().min, glm::vec3(10.0f - 1.0f, -3.0f + 0.25f, 1.0f));
  EXPECT_EQ(f.bounds().max, glm::vec3(10.0f + 1.5f, -3.0f + 1.0f, 1.0f + 4.0f));
  EXPECT_FALSE(report.resampled);
  // Exact copies of the voxels: voxel (-2 + i, 1 + j, k) is point (i, j, k).
  expectAsymmetricAt(f, 1e-5f);
  EXPECT_FLOAT_EQ(f.at(1, 0, 0).x, 10.0f - 0.5f + 1.0f);
}

TEST(VdbFormat, RotatedTransformIsHonoured) {
  const auto dir = test::scratch();
  auto xform = openvdb::math::Transform::createLinearTransform(0.5);
  xform->postRotate(M_PI / 2, openvdb::math::Z_AXIS);  // index x -> world y, index y -> world -x
  xform->postTranslate(openvdb::Vec3d(1.0, 2.0, 3.0));
  const openvdb::CoordBBox box(openvdb::Coord(0, 0, 0), openvdb::Coord(4, 2, 3));
  const auto path = dir / "rotated.vdb";
  write(path, {asymmetricGrid(xform, box)});
  const VectorField f = loadField(path);
  // Index x (5 voxels) runs along world y, index y (3 voxels) along world -x.
  EXPECT_NEAR(f.bounds().min.x, 1.0f - 1.0f, 1e-5f);
  EXPECT_NEAR(f.bounds().max.x, 1.0f, 1e-5f);
  EXPECT_NEAR(f.bounds().min.y, 2.0f, 1e-5f);
  EXPECT_NEAR(f.bounds().max.y, 4.0f, 1e-5f);
  EXPECT_EQ(f.dims(), glm::ivec3(3, 5, 4));
  expectAsymmetricAt(f, 1e-4f);
}

TEST(VdbFormat, StaggeredGridsAreSampledAtVoxelCentres) {
  initializeOpenVdb();
  const auto dir = test::scratch();
  auto xform = openvdb::math::Transform::createLinearTransform(0.5);
  auto grid = openvdb::Vec3SGrid::create();
  grid->setTransform(xform);
  grid->setName("mac");
  grid->setGridClass(openvdb::GRID_STAGGERED);
  auto acc = grid->getAccessor();
  const openvdb::CoordBBox box(openvdb::Coord(0), openvdb::Coord(5));
  for (auto it = box.begin(); it; ++it) {
    // MAC layout: component a lives on the voxel's -a face.
    const openvdb::Vec3d c = xform->indexToWorld(*it);
    const double h = 0.25;
    acc.setValueOn(*it, openvdb::Vec3s(float(asymmetric({c.x() - h, c.y(), c.z()}).x),
                                       float(asymmetric({c.x(), c.y() - h, c.z()}).y),
                                       float(asymmetric({c.x(), c.y(), c.z() - h}).z)));
  }
  const auto path = dir / "mac.vdb";
  write(path, {grid});
  LoadReport report;
  const VectorField f = loadField(path, {}, &report);
  // Six voxels a side, the last layer without its upper faces: five cells
  // whose faces all exist, every centre value exact, boundary included
  // (sampling the faces as cell-centred values would be off by half a voxel;
  // averaging with a missing face, by half the velocity).
  EXPECT_EQ(f.dims(), glm::ivec3(5));
  expectAsymmetricAt(f, 1e-4f, 0);
  ASSERT_FALSE(report.notes.empty());
}

TEST(VdbFormat, AUniformMacFlowIsUniformUpToItsBoundary) {
  // 1 m/s along x on every face of a MAC grid: the loaded field is 1 m/s
  // everywhere, its outermost layer too (not 0.5 where a face is missing).
  initializeOpenVdb();
  const auto dir = test::scratch();
  auto grid = openvdb::Vec3SGrid::create();
  grid->setTransform(openvdb::math::Transform::createLinearTransform(0.25));
  grid->setName("mac");
  grid->setGridClass(openvdb::GRID_STAGGERED);
  grid->fill(openvdb::CoordBBox(openvdb::Coord(-3), openvdb::Coord(4)), openvdb::Vec3s(1, 0, 0));
  const auto path = dir / "uniform.vdb";
  write(path, {grid});
  const VectorField f = loadField(path);
  EXPECT_EQ(f.dims(), glm::ivec3(7));
  for (const glm::vec3& v : f.values())
    ASSERT_EQ(v, glm::vec3(1, 0, 0));
}

TEST(VdbFormat, SparseGridsAreDensifiedOverTheActiveBox) {
  initializeOpenVdb();
  const auto dir = test::scratch();
  auto grid = openvdb::Vec3SGrid::create();
  grid->setName("v");
  grid->tree().setValueOn(openvdb::Coord(0, 0, 0), openvdb::Vec3s(1, 2, 3));
  grid->tree().setValueOn(openvdb::Coord(9, 4, 2), openvdb::Vec3s(-1, -2, -3));
  const auto path = dir / "sparse.vdb";
  write(path, {grid});
  const VectorField f = loadField(path);
  EXPECT_EQ(f.dims(), glm::ivec3(10, 5, 3));
  EXPECT_EQ(f.at(0, 0, 0), glm::vec3(1, 2, 3));
  EXPECT_EQ(f.at(9, 4, 2), glm::vec3(-1, -2, -3));
  EXPECT_EQ(f.at(5, 2, 1), glm::vec3(0.0f));  // background between them
}

TEST(VdbFormat, RefusesADenseCopyBeyondTheBudgetAndSaysHowToFit) {
  initializeOpenVdb();
  const auto dir = test::scratch();
  auto grid = openvdb::Vec3SGrid::create();
  grid->setName("v");
  grid->tree().setValueOn(openvdb::Coord(0, 0, 0), openvdb::Vec3s(1, 0, 0));
  grid->tree().setValueOn(openvdb::Coord(1999, 1999, 1999), openvdb::Vec3s(0, 1, 0));
  const auto path = dir / "huge.vdb";
  write(path, {grid});
  test::expectError([&] { loadField(path); },
                    {path.string(), "2000x2000x2000", "memory budget", "--dims"});
  LoadOptions o;
  o.resolution = {20, 20, 20};
  const VectorField f = loadField(path, o);
  EXPECT_EQ(f.dims(), glm::ivec3(20));
  EXPECT_EQ(f.at(0, 0, 0), glm::vec3(1, 0, 0));
  EXPECT_EQ(f.at(19, 19, 19), glm::vec3(0, 1, 0));
}

TEST(VdbFormat, GridsAreChosenByNameAndListedWhenWrong) {
  initializeOpenVdb();
  const auto dir = test::scratch();
  auto a = openvdb::Vec3SGrid::create();
  a->setName("vel");
  a->tree().setValueOn(openvdb::Coord(0), openvdb::Vec3s(1, 0, 0));
  auto b = openvdb::Vec3DGrid::create();
  b->setName("wind");
  b->tree().setValueOn(openvdb::Coord(0), openvdb::Vec3d(0, 2, 0));
  auto c = openvdb::FloatGrid::create();
  c->setName("density");
  c->tree().setValueOn(openvdb::Coord(0), 1.0f);
  const auto path = dir / "grids.vdb";
  write(path, {a, b, c});
  test::expectError([&] { loadField(path); }, {path.string(), "several Vec3 grids", "'vel' (vec3s)",
                                               "'wind' (vec3d)", "'density' (float)"});
  LoadOptions o;
  o.arrayName = "wind";
  EXPECT_EQ(loadField(path, o).at(0, 0, 0), glm::vec3(0, 2, 0));
  o.arrayName = "density";
  test::expectError([&] { loadField(path, o); },
                    {path.string(), "'density' holds float values", "expected a Vec3 grid"});
  o.arrayName = "velocity";
  test::expectError([&] { loadField(path, o); },
                    {path.string(), "no grid named 'velocity'", "'vel' (vec3s)"});
  const auto scalars = dir / "scalars.vdb";
  write(scalars, {c});
  test::expectError([&] { loadField(scalars); }, {scalars.string(), "no Vec3 grid", "density"});
}

// Float and double grids come along as scalar arrays, sampled at the field's
// points even on a transform of their own: density = 2 x - y + 3 z is linear,
// so trilinear sampling gives it exactly.
TEST(VdbFormat, ScalarGridsBecomeTheFieldsArrays) {
  const auto dir = test::scratch();
  const auto coarse = openvdb::math::Transform::createLinearTransform(0.5);
  auto fine = openvdb::math::Transform::createLinearTransform(0.25);
  fine->postTranslate(openvdb::Vec3d(-0.5, 0.0, 0.25));
  auto vel = asymmetricGrid(coarse, openvdb::CoordBBox({0, 0, 0}, {4, 3, 2}));
  auto density = openvdb::DoubleGrid::create();
  density->setTransform(fine);
  density->setName("density");
  auto temperature = openvdb::FloatGrid::create();
  temperature->setTransform(coarse->copy());
  temperature->setName("temperature");
  auto d = density->getAccessor();
  auto t = temperature->getAccessor();
  for (auto it = openvdb::CoordBBox({-2, -2, -3}, {12, 10, 8}).begin(); it; ++it) {
    const openvdb::Vec3d w = fine->indexToWorld(*it);
    d.setValueOn(*it, 2.0 * w.x() - w.y() + 3.0 * w.z());
  }
  for (auto it = openvdb::CoordBBox({0, 0, 0}, {4, 3, 2}).begin(); it; ++it)
    t.setValueOn(*it, 280.0f + float((*it).x()));
  const auto path = dir / "scalars.vdb";
  write(path, {vel, density, temperature});
  const VectorField f = loadField(path);
  ASSERT_EQ(f.scalars().size(), 2u) << f.scalarNames();
  const VectorField::Scalars* dens = f.findScalars("density");
  const VectorField::Scalars* temp = f.findScalars("temperature");
  ASSERT_TRUE(dens && temp);
  for (int k = 0; k < f.dims().z; ++k)
    for (int j = 0; j < f.dims().y; ++j)
      for (int i = 0; i < f.dims().x; ++i) {
        const glm::vec3 p = f.pointPosition(i, j, k);
        EXPECT_NEAR(dens->values[f.index(i, j, k)], 2.0f * p.x - p.y + 3.0f * p.z, 1e-4f);
        EXPECT_NEAR(temp->values[f.index(i, j, k)], 280.0f + float(i), 1e-4f);
      }
}

TEST(VdbFormat, OurWritersKeepTheScalarArrays) {
  const auto dir = test::scratch();
  VectorField f(Box{{-1.0f, 0.0f, 2.0f}, {1.0f, 3.0f, 3.0f}}, {3, 4, 2});
  std::vector<float> t(f.pointCount());
  for (std::size_t i = 0; i < t.size(); ++i)
    t[i] = 0.5f * float(i) - 3.0f;
  f.addScalars("temperature", t);
  for (const char* name : {"ours.vdb", "ours.vti"}) {
    saveField(dir / name, f);
    const VectorField g = loadField(dir / name);
    const VectorField::Scalars* back = g.findScalars("temperature");
    ASSERT_TRUE(back) << name << ": " << g.scalarNames();
    for (std::size_t i = 0; i < t.size(); ++i)
      EXPECT_NEAR(back->values[i], t[i], 1e-5f) << name << " point " << i;
  }
}

TEST(VdbFormat, OurVdbReadsBackThroughOpenVdbUnchanged) {
  const auto dir = test::scratch();
  const glm::ivec3 dims(4, 5, 3);
  VectorField f(Box{{-2.0f, 0.0f, 5.0f}, {1.0f, 2.0f, 6.0f}}, dims);
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i)
        f.at(i, j, k) = glm::vec3(asymmetric(glm::dvec3(f.pointPosition(i, j, k))));
  const auto path = dir / "ours.vdb";
  writeVdb(path, f, "velocity");

  openvdb::io::File file(path.string());
  file.open();
  auto grid = openvdb::gridPtrCast<openvdb::Vec3SGrid>(file.readGrid("velocity"));
  file.close();
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->activeVoxelCount(), openvdb::Index64(dims.x * dims.y * dims.z));
  auto acc = grid->getConstAccessor();
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) {
        const openvdb::Vec3s v = acc.getValue(openvdb::Coord(i, j, k));
        EXPECT_EQ(glm::vec3(v.x(), v.y(), v.z()), f.at(i, j, k));
        const openvdb::Vec3d w = grid->transform().indexToWorld(openvdb::Coord(i, j, k));
        const glm::vec3 p = f.pointPosition(i, j, k);
        EXPECT_NEAR(w.x(), p.x, 1e-5);
        EXPECT_NEAR(w.y(), p.y, 1e-5);
        EXPECT_NEAR(w.z(), p.z, 1e-5);
      }
  const VectorField g = loadField(path);
  EXPECT_EQ(g.dims(), dims);
  for (std::size_t i = 0; i < f.pointCount(); ++i)
    EXPECT_EQ(g.values()[i], f.values()[i]);
}

}  // namespace
}  // namespace sandstorm
