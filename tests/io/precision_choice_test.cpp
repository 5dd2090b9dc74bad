// field.precision = "auto" (core/io/precision_choice.h): a field whose floats
// would not fit the room the GPU has for fields is kept as halves, and says
// so; one that fits, one with a component halves cannot hold, and one whose
// precision was asked for stay as they are.
#include "core/io/precision_choice.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sandstorm {
namespace {

VectorField wind(glm::vec3 v, glm::ivec3 dims = glm::ivec3(10)) {
  return VectorField(Box{{0, 0, 0}, {1, 1, 1}}, dims,
                     std::vector<glm::vec3>(std::size_t(dims.x) * dims.y * dims.z, v));
}

LoadOptions room(double bytes) {
  LoadOptions o;
  o.gpuRoom = [bytes](double) { return std::optional<double>(bytes); };
  return o;
}

TEST(PrecisionChoice, FloatsThatWouldNotFitBecomeHalvesAndSaySo) {
  // 1000 points: 16 000 bytes as floats, 48 000 for a series' three grids.
  const glm::vec3 v(0.1f, -2.3456789f, 1000.123f);
  for (const auto& [grids, bytes, half] :
       {std::tuple{1, 20000.0, false}, std::tuple{1, 10000.0, true}, std::tuple{3, 20000.0, true},
        std::tuple{3, 50000.0, false}}) {
    SCOPED_TRACE(testing::Message() << grids << " grid(s), room " << bytes);
    VectorField f = wind(v);
    LoadReport report;
    EXPECT_EQ(chooseHalf(f, grids, room(bytes), report), half);
    EXPECT_EQ(f.halfPrecision(), half);
    EXPECT_EQ(floatGpuBytes(f, grids), 16000.0 * grids);
    if (!half) {
      EXPECT_TRUE(report.notes.empty());
      EXPECT_EQ(f.values()[0], v);
      continue;
    }
    ASSERT_EQ(report.notes.size(), 1u);
    EXPECT_NE(report.notes[0].find("field.precision = \"auto\": 16-bit floats chosen"),
              std::string::npos)
        << report.notes[0];
    // Each component rounded to the nearest half: within 2^-11 of itself.
    for (int c = 0; c < 3; ++c) {
      EXPECT_NE(f.values()[0][c], v[c]);
      EXPECT_LE(std::abs(f.values()[0][c] - v[c]), std::abs(v[c]) * std::ldexp(1.0f, -11));
    }
  }
}

TEST(PrecisionChoice, AMaskedFieldTakesAsMuchAndAnAskedPrecisionOrNoAnswerIsKept) {
  VectorField masked = wind(glm::vec3(1.0f));
  std::vector<std::uint8_t> valid(1000, 1);
  valid[0] = 0;  // one point outside the data
  masked.setValidity(std::move(valid));
  EXPECT_EQ(floatGpuBytes(masked, 1), 16000.0);  // RGBA32F, the mask in alpha
  LoadReport report;
  EXPECT_TRUE(chooseHalf(masked, 1, room(15000.0), report));

  VectorField asked = wind(glm::vec3(0.1f));
  LoadOptions floats = room(1.0);
  floats.gpuRoom = nullptr;  // field.precision = "float"
  EXPECT_FALSE(chooseHalf(asked, 1, floats, report));
  LoadOptions silent;
  silent.gpuRoom = [](double) { return std::optional<double>(); };  // no GPU answers
  EXPECT_FALSE(chooseHalf(asked, 1, silent, report));
  EXPECT_FALSE(asked.halfPrecision());
}

TEST(PrecisionChoice, AComponentHalvesCannotHoldKeepsFloatsAndSaysWhy) {
  VectorField f = wind(glm::vec3(1.0f, 70000.0f, 0.0f));
  LoadReport report;
  EXPECT_FALSE(chooseHalf(f, 1, room(1.0), report));
  EXPECT_FALSE(f.halfPrecision());
  EXPECT_EQ(f.values()[5], glm::vec3(1.0f, 70000.0f, 0.0f));  // untouched
  ASSERT_EQ(report.notes.size(), 1u);
  EXPECT_NE(report.notes[0].find("kept as floats"), std::string::npos) << report.notes[0];
  EXPECT_NE(report.notes[0].find("field.resolution"), std::string::npos) << report.notes[0];
}

}  // namespace
}  // namespace sandstorm
