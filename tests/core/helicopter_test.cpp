// The downdraft demo's interaction model (thesis chapter 6) and its pieces.
#include "core/sim/helicopter.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/field/height_map_io.h"
#include "core/field/vortex_ring_field.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

TEST(Helicopter, MoreThrottleRaisesMoreDust) {
  const HelicopterModel m;
  HelicopterSettings s;
  s.altitude = 5.0f;
  HelicopterEffects previous{};
  for (float throttle : {0.2f, 0.5f, 0.8f, 1.0f}) {
    s.throttle = throttle;
    const HelicopterEffects e = helicopterEffects(s, m);
    EXPECT_GT(e.thrust, previous.thrust);
    EXPECT_GT(e.rate, previous.rate);
    EXPECT_GT(e.lifetime, previous.lifetime);
    EXPECT_GE(e.maximum, previous.maximum);
    previous = e;
  }
  // Full throttle is 1.25 times the weight.
  EXPECT_NEAR(previous.thrust, 1.25f * m.mass * 9.81f, 1.0f);
}

TEST(Helicopter, ClimbingPastTheWashsReachLowersTheDust) {
  const HelicopterModel m;
  HelicopterSettings s;
  s.throttle = 0.8f;
  s.altitude = m.fullEffectHeight * m.rotorRadius;  // low: all the dust it can
  const HelicopterEffects low = helicopterEffects(s, m);
  s.altitude = 2.5f * m.rotorRadius;
  const HelicopterEffects mid = helicopterEffects(s, m);
  s.altitude = m.noEffectHeight * m.rotorRadius + 1.0f;
  const HelicopterEffects high = helicopterEffects(s, m);
  EXPECT_FLOAT_EQ(low.groundEffect, 1.0f);
  EXPECT_NEAR(mid.groundEffect, 0.5f, 1e-5f);
  EXPECT_FLOAT_EQ(high.groundEffect, 0.0f);
  EXPECT_GT(low.rate, mid.rate);
  EXPECT_EQ(high.rate, 0.0f);
  EXPECT_GT(low.lifetime, high.lifetime);
  EXPECT_GT(low.maximum, high.maximum);
}

TEST(VortexRing, LiftsTheWallJetOutsideAndDrawsItInAbove) {
  VortexRingParams p;
  p.ringRadius = 10.0f;
  p.height = 3.0f;
  p.core = 2.0f;
  p.strength = 4.0f;
  const VortexRingField ring(p);
  const glm::vec3 below = ring.evaluate({10.0f, 0.0f, 1.0f});    // under the core: outwards
  const glm::vec3 outside = ring.evaluate({12.0f, 0.0f, 3.0f});  // outer side: up
  const glm::vec3 above = ring.evaluate({0.0f, 10.0f, 5.0f});    // above (on the y axis): inwards
  EXPECT_GT(below.x, 0.0f);
  EXPECT_GT(outside.z, 0.0f);
  EXPECT_LT(above.y, 0.0f);
  EXPECT_NEAR(glm::length(outside), p.strength, 1e-4f);  // the peak speed sits one core radius out
}

TEST(HeightMapPgm, RoundTripsAndReadsNorthUp) {
  const auto path = std::filesystem::temp_directory_path() / "sandstorm-height.pgm";
  std::vector<float> h(4 * 3);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i)
      h[std::size_t(j * 4 + i)] = 0.5f * float(i) + 2.0f * float(j);
  const HeightMap map({-2, -1}, {2, 1}, {4, 3}, h);
  writeHeightMapPgm(map, path, 0.0f, 10.0f);
  const HeightMap back = readHeightMapPgm(path, Box{{-2, -1, 0}, {2, 1, 10}});
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i)
      EXPECT_NEAR(back.at(i, j), map.at(i, j), 10.0f / 65535.0f);
  // The file's first sample row is the northern edge (largest y), as an image of a map is.
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int i = 0; i < 4; ++i)
    std::getline(in, line);  // magic, comment, size, maxval
  const int first = (in.get() << 8) | in.get();
  EXPECT_NEAR(first / 65535.0f * 10.0f, map.at(0, 2), 1e-3f);
}

TEST(HeightMapPgm, BadFilesFailClearly) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto write = [&](const std::string& name, const std::string& bytes) {
    std::ofstream(dir / name, std::ios::binary) << bytes;
    return dir / name;
  };
  const Box extent{{0, 0, 0}, {1, 1, 1}};
  const auto expectError = [&](const std::filesystem::path& p, const std::string& part) {
    try {
      readHeightMapPgm(p, extent);
      ADD_FAILURE() << "no error for " << p;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  expectError(write("a.pgm", "P2\n2 2\n255\n0 0 0 0\n"), "expected the magic 'P5'");
  expectError(write("b.pgm", "P5\n2 2\n65535\n\x01\x02"), "truncated");
  expectError(write("c.pgm", "P5\n0 2\n255\n"), "width 0");
  expectError(write("d.pgm", "P5\nx 2\n255\n"), "'x' is not a number");
  expectError(dir / "missing.pgm", "cannot open");
}

}  // namespace
}  // namespace sandstorm
