// ColorMap against the maps' published colours and Moreland's paper.
#include "core/color/color_map.h"

#include <gtest/gtest.h>

namespace sandstorm {
namespace {

glm::vec3 rgb(int r, int g, int b) {
  return glm::vec3(float(r), float(g), float(b)) / 255.0f;
}

void expectColor(glm::vec3 got, glm::vec3 want, float tolerance, const char* what) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c], want[c], tolerance) << what << ", channel " << c;
}

float luminance(glm::vec3 c) {
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

TEST(ColorMap, PerceptualMapsHaveTheirPublishedEndsAndMiddles) {
  // matplotlib's viridis(0), viridis(0.5), viridis(1), and likewise.
  expectColor(ColorMap(ColorMapName::Viridis).at(0.0f), rgb(0x44, 0x01, 0x54), 1e-6f, "viridis 0");
  expectColor(ColorMap(ColorMapName::Viridis).at(0.5f), rgb(0x21, 0x91, 0x8c), 1e-6f, "viridis .5");
  expectColor(ColorMap(ColorMapName::Viridis).at(1.0f), rgb(0xfd, 0xe7, 0x25), 1e-6f, "viridis 1");
  expectColor(ColorMap(ColorMapName::Plasma).at(0.0f), rgb(0x0d, 0x08, 0x87), 1e-6f, "plasma 0");
  expectColor(ColorMap(ColorMapName::Plasma).at(1.0f), rgb(0xf0, 0xf9, 0x21), 1e-6f, "plasma 1");
  expectColor(ColorMap(ColorMapName::Inferno).at(0.0f), rgb(0x00, 0x00, 0x04), 1e-6f, "inferno 0");
  expectColor(ColorMap(ColorMapName::Inferno).at(1.0f), rgb(0xfc, 0xff, 0xa4), 1e-6f, "inferno 1");
  expectColor(ColorMap(ColorMapName::Cividis).at(0.0f), rgb(0x00, 0x22, 0x4e), 1e-6f, "cividis 0");
  expectColor(ColorMap(ColorMapName::Cividis).at(1.0f), rgb(0xfe, 0xe8, 0x38), 1e-6f, "cividis 1");
}

TEST(ColorMap, SequentialMapsGetBrighterAllTheWay) {
  for (const ColorMapName name :
       {ColorMapName::Viridis, ColorMapName::Plasma, ColorMapName::Inferno, ColorMapName::Cividis,
        ColorMapName::Grey}) {
    const ColorMap map(name);
    float previous = -1.0f;
    for (int i = 0; i <= 100; ++i) {
      const float l = luminance(map.at(float(i) / 100.0f));
      EXPECT_GT(l, previous) << "map " << int(name) << " at t = " << float(i) / 100.0f;
      previous = l;
    }
  }
}

TEST(ColorMap, CoolWarmIsMorelandsDivergingMap) {
  // Moreland (2009), table of the cool-to-warm map: ends (59, 76, 192) and
  // (180, 4, 38), a neutral grey of about (221, 221, 221) in the middle.
  const ColorMap map(ColorMapName::CoolWarm);
  expectColor(map.at(0.0f), rgb(59, 76, 192), 1.0f / 255.0f, "cool end");
  expectColor(map.at(1.0f), rgb(180, 4, 38), 1.0f / 255.0f, "warm end");
  expectColor(map.at(0.5f), rgb(221, 221, 221), 1.0f / 255.0f, "middle");
  // Further rows of his table (at eighths).
  expectColor(map.at(0.125f), rgb(98, 130, 234), 1.0f / 255.0f, "0.125");
  expectColor(map.at(0.25f), rgb(141, 176, 254), 1.0f / 255.0f, "0.25");
  expectColor(map.at(0.375f), rgb(184, 208, 249), 1.0f / 255.0f, "0.375");
  expectColor(map.at(0.625f), rgb(245, 196, 173), 1.0f / 255.0f, "0.625");
  expectColor(map.at(0.75f), rgb(244, 154, 123), 1.0f / 255.0f, "0.75");
  expectColor(map.at(0.875f), rgb(222, 97, 77), 1.0f / 255.0f, "0.875");
  // Lightness rises to the middle and falls after it.
  EXPECT_LT(luminance(map.at(0.25f)), luminance(map.at(0.5f)));
  EXPECT_LT(luminance(map.at(0.75f)), luminance(map.at(0.5f)));
  // Blue below the middle, red above.
  EXPECT_GT(map.at(0.25f).z, map.at(0.25f).x);
  EXPECT_GT(map.at(0.75f).x, map.at(0.75f).z);
}

// ParaView's "Fast": its control points are its colours there, and between
// them the path is straight in CIELAB, not in sRGB (VTK's own interpolation is
// compared in tests/io/color_map_vtk_test.cpp).
TEST(ColorMap, FastPassesThroughItsControlPointsAndIsDarkAtBothEnds) {
  const ColorMap map(ColorMapName::Fast);
  expectColor(map.at(0.0f), glm::vec3(0.0564f, 0.0564f, 0.47f), 0.5f / 255.0f, "low end");
  expectColor(map.at(0.5f), glm::vec3(0.89949596f, 0.9446464f, 0.76865671f), 0.5f / 255.0f,
              "middle");
  expectColor(map.at(0.84763953f), glm::vec3(0.8f, 0.352f, 0.16f), 0.5f / 255.0f, "0.848");
  expectColor(map.at(1.0f), glm::vec3(0.59f, 0.0767f, 0.119475f), 0.5f / 255.0f, "high end");
  // Light in the middle, dark at the ends: a diverging map.
  EXPECT_GT(luminance(map.at(0.5f)), luminance(map.at(0.25f)));
  EXPECT_GT(luminance(map.at(0.5f)), luminance(map.at(0.75f)));
  EXPECT_GT(luminance(map.at(0.25f)), luminance(map.at(0.0f)));
  EXPECT_GT(luminance(map.at(0.75f)), luminance(map.at(1.0f)));
}

TEST(ColorMap, LifeGoesFromBirthToDeathColour) {
  const ColorMap map(ColorMapName::Life, glm::vec3(1, 0, 0), glm::vec3(0, 0, 1));
  expectColor(map.at(0.25f), glm::vec3(0.75f, 0.0f, 0.25f), 1e-6f, "a quarter of life");
  expectColor(ColorMap(ColorMapName::Grey).at(0.3f), glm::vec3(0.3f), 1e-6f, "grey");
}

TEST(ColorMap, OutOfRangeAndNonFiniteCoordinatesAreClamped) {
  const ColorMap map(ColorMapName::Viridis);
  expectColor(map.at(-3.0f), map.at(0.0f), 0.0f, "below");
  expectColor(map.at(7.0f), map.at(1.0f), 0.0f, "above");
  expectColor(map.at(std::numeric_limits<float>::quiet_NaN()), map.at(0.0f), 0.0f, "NaN");
}

// The listed maps' stops are samples of the table, so between them the table
// is exact; cool-warm and fast bend between samples (Msh and Lab paths).
TEST(ColorMap, TheGpuTableIsWithinOneStepOfEightBitsOfTheMap) {
  for (const ColorMapName name :
       {ColorMapName::Viridis, ColorMapName::Plasma, ColorMapName::Inferno, ColorMapName::Cividis,
        ColorMapName::CoolWarm, ColorMapName::Fast}) {
    const ColorMap map(name);
    const ColorMap::Table table = map.gpuTable();
    float worst = 0.0f;
    for (int i = 0; i <= 1000; ++i) {
      const float t = float(i) / 1000.0f;
      const glm::vec3 d = glm::abs(ColorMap::lookupTable(table, t) - map.at(t));
      worst = std::max({worst, d.x, d.y, d.z});
    }
    const bool curved = name == ColorMapName::CoolWarm || name == ColorMapName::Fast;
    EXPECT_LT(worst, (curved ? 1.5f : 0.01f) / 255.0f) << "map " << int(name);
  }
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

TEST(ColorTableCache, GivesTheMapsTableAndFollowsItsChanges) {
  ColorTableCache cache;
  const glm::vec3 red(1, 0, 0), blue(0, 0, 1);
  EXPECT_EQ(cache.get(ColorMapName::Viridis, red, blue),
            ColorMap(ColorMapName::Viridis).gpuTable());
  EXPECT_EQ(cache.get(ColorMapName::Life, red, blue),
            ColorMap(ColorMapName::Life, red, blue).gpuTable());
  // Life follows its colours; the others do not depend on them.
  EXPECT_EQ(cache.get(ColorMapName::Life, blue, red),
            ColorMap(ColorMapName::Life, blue, red).gpuTable());
  EXPECT_EQ(cache.get(ColorMapName::CoolWarm, red, red),
            ColorMap(ColorMapName::CoolWarm).gpuTable());
}

}  // namespace
}  // namespace sandstorm
