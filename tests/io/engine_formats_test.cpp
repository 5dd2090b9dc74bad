// Unreal FGA and Unity VF files, written here byte by byte from their
// published layouts, load with values and axes converted to Sandstorm's.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <sstream>

#include "core/io/field_loader.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

using test::asymmetric;

struct Voxel {
  glm::dvec3 position;  // in the engine's axes and units
  glm::dvec3 value;
};

// An FGA whose vector at each voxel centre is the asymmetric field there.
std::vector<Voxel> writeFga(const std::filesystem::path& path, glm::ivec3 n, glm::dvec3 lo,
                            glm::dvec3 hi) {
  std::ostringstream os;
  os << n.x << "," << n.y << "," << n.z << ",\n"
     << lo.x << "," << lo.y << "," << lo.z << ",\n"
     << hi.x << "," << hi.y << "," << hi.z << ",\n";
  std::vector<Voxel> voxels;
  for (int k = 0; k < n.z; ++k)
    for (int j = 0; j < n.y; ++j)
      for (int i = 0; i < n.x; ++i) {
        const glm::dvec3 p = lo + (glm::dvec3(i, j, k) + 0.5) * (hi - lo) / glm::dvec3(n);
        const glm::dvec3 v = asymmetric(p);
        os << v.x << "," << v.y << "," << v.z << ",\n";
        voxels.push_back({p, v});
      }
  test::writeText(path, os.str());
  return voxels;
}

std::vector<Voxel> writeVf(const std::filesystem::path& path, glm::ivec3 n, const Box& box,
                           const float* matrix = nullptr) {
  std::string bytes = matrix ? "VF2X" : "VF_V";
  if (matrix) bytes += std::string{char(0), char(2), char(2)};
  for (int a = 0; a < 3; ++a) {
    const std::uint16_t d = std::uint16_t(n[a]);
    bytes.append(reinterpret_cast<const char*>(&d), 2);
  }
  if (matrix) bytes.append(reinterpret_cast<const char*>(matrix), 64);
  std::vector<Voxel> voxels;
  for (int k = 0; k < n.z; ++k)
    for (int j = 0; j < n.y; ++j)
      for (int i = 0; i < n.x; ++i) {
        const glm::dvec3 p = glm::dvec3(box.min) + (glm::dvec3(i, j, k) + 0.5) *
                                                       glm::dvec3(box.max - box.min) /
                                                       glm::dvec3(n);
        const glm::vec3 v(asymmetric(p));
        bytes.append(reinterpret_cast<const char*>(&v), 12);
        voxels.push_back({p, glm::dvec3(v)});
      }
  test::writeText(path, bytes);
  return voxels;
}

TEST(EngineFormats, UnrealFgaBecomesRightHandedMetres) {
  const auto dir = test::scratch();
  const auto path = dir / "field.fga";
  const auto voxels = writeFga(path, {4, 3, 2}, {-100, 0, 50}, {300, 300, 250});
  LoadReport report;
  const VectorField f = loadField(path, {}, &report);
  EXPECT_EQ(f.dims(), glm::ivec3(4, 3, 2));
  // Voxel centres in metres, y mirrored.
  EXPECT_NEAR(f.bounds().min.x, -0.5f, 1e-6f);
  EXPECT_NEAR(f.bounds().max.x, 2.5f, 1e-6f);
  EXPECT_NEAR(f.bounds().min.y, -2.5f, 1e-6f);
  EXPECT_NEAR(f.bounds().max.y, -0.5f, 1e-6f);
  EXPECT_NEAR(f.bounds().min.z, 1.0f, 1e-6f);
  EXPECT_NEAR(f.bounds().max.z, 2.0f, 1e-6f);
  for (const Voxel& v : voxels) {
    const glm::vec3 at(0.01 * v.position.x, -0.01 * v.position.y, 0.01 * v.position.z);
    const glm::vec3 expected(0.01 * v.value.x, -0.01 * v.value.y, 0.01 * v.value.z);
    EXPECT_NEAR(glm::length(f.sample(at) - expected), 0.0f, 1e-5f);
  }
  LoadOptions raw;
  raw.convertEngineAxes = false;
  const VectorField g = loadField(path, raw);
  EXPECT_NEAR(g.bounds().min.x, -50.0f, 1e-4f);
  for (const Voxel& v : voxels)
    EXPECT_NEAR(glm::length(g.sample(glm::vec3(v.position)) - glm::vec3(v.value)), 0.0f, 1e-4f);
}

TEST(EngineFormats, UnityVfBecomesZUp) {
  const auto dir = test::scratch();
  const auto path = dir / "field.vf";
  const Box unit{glm::vec3(-0.5f), glm::vec3(0.5f)};
  const auto voxels = writeVf(path, {3, 4, 2}, unit);
  const VectorField f = loadField(path);
  // Unity's (x, y-up, z-forward) grid of 3x4x2 becomes 3 (x) by 2 (north) by 4 (up).
  EXPECT_EQ(f.dims(), glm::ivec3(3, 2, 4));
  for (const Voxel& v : voxels) {
    const glm::vec3 at(v.position.x, v.position.z, v.position.y);
    const glm::vec3 expected(v.value.x, v.value.z, v.value.y);
    EXPECT_NEAR(glm::length(f.sample(at) - expected), 0.0f, 1e-5f);
  }
  LoadOptions o;
  o.unityBounds = Box{{0, 0, 0}, {3, 8, 4}};
  const VectorField big = loadField(path, o);
  EXPECT_NEAR(big.bounds().max.z, 8.0f - 1.0f, 1e-5f);  // Unity y (8 m, 4 voxels) is up
}

TEST(EngineFormats, UnityVf2PlacesTheUnitBoxWithItsMatrix) {
  const auto dir = test::scratch();
  const auto path = dir / "field2.vf";
  float m[16] = {2, 0, 0, 0, 0, 4, 0, 0, 0, 0, 6, 0, 1, 2, 3, 1};  // scale, then translation
  const Box box{{0.0f, 0.0f, 0.0f}, {2.0f, 4.0f, 6.0f}};
  const auto voxels = writeVf(path, {2, 2, 3}, box, m);
  const VectorField f = loadField(path);
  EXPECT_NEAR(f.bounds().min.x, 0.5f, 1e-6f);
  EXPECT_NEAR(f.bounds().max.x, 1.5f, 1e-6f);
  EXPECT_NEAR(f.bounds().min.z, 1.0f, 1e-6f);  // Unity y: 0..4 in 2 voxels
  EXPECT_NEAR(f.bounds().max.z, 3.0f, 1e-6f);
  for (const Voxel& v : voxels) {
    const glm::vec3 at(v.position.x, v.position.z, v.position.y);
    EXPECT_NEAR(glm::length(f.sample(at) - glm::vec3(v.value.x, v.value.z, v.value.y)), 0.0f,
                1e-5f);
  }
}

TEST(EngineFormats, ResampledToAnotherResolution) {
  const auto dir = test::scratch();
  const auto path = dir / "field.fga";
  writeFga(path, {4, 3, 2}, {-100, 0, 50}, {300, 300, 250});
  LoadOptions o;
  o.resolution = {7, 5, 3};
  LoadReport report;
  const VectorField f = loadField(path, o, &report);
  EXPECT_TRUE(report.resampled);
  EXPECT_EQ(f.dims(), glm::ivec3(7, 5, 3));
  const glm::vec3 p = f.pointPosition(3, 2, 1);  // back to Unreal centimetres
  const glm::dvec3 u(100.0 * p.x, -100.0 * p.y, 100.0 * p.z);
  const glm::dvec3 v = asymmetric(u);
  EXPECT_NEAR(glm::length(f.at(3, 2, 1) - glm::vec3(0.01 * v.x, -0.01 * v.y, 0.01 * v.z)), 0.0f,
              1e-4f);
}

}  // namespace
}  // namespace sandstorm
