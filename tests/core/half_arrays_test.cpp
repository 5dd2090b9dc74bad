// Half floats by the million (core/util/half_arrays.h) against the one-at-a-
// time functions, which half_float_test.cpp checks against the definition:
// every finite half, the floats around every midpoint between two halves,
// and lengths that leave a tail beside the eight-at-a-time part. On a CPU
// with F16C this checks F16C's conversions; elsewhere the same functions.
#include "core/util/half_arrays.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "core/util/half_float.h"

namespace sandstorm {
namespace {

// Every finite half as a float, both signs.
std::vector<float> everyHalf() {
  std::vector<float> out;
  for (std::uint32_t h = 0; h < 65536; ++h)
    if (((h >> 10) & 0x1f) != 0x1f) out.push_back(halfToFloat(std::uint16_t(h)));
  return out;
}

TEST(HalfArrays, RoundingAGridRoundsEachValueAsNearestHalfDoes) {
  // The floats at, below and above the midpoint of every pair of
  // neighbouring halves, both signs, and a few more to leave a tail.
  std::vector<float> values;
  for (std::uint16_t low = 0; low < 0x7bff; ++low) {
    const float a = halfToFloat(low), b = halfToFloat(std::uint16_t(low + 1));
    const float mid = float((double(a) + double(b)) / 2);
    for (const float x : {mid, std::nextafter(mid, 0.0f), std::nextafter(mid, 1e9f), a})
      values.insert(values.end(), {x, -x});
  }
  values.insert(values.end(), {65504.0f, -65504.0f, 1e-30f, -0.0f, 0.1f});
  ASSERT_NE(values.size() % 8, 0u);
  std::vector<float> rounded = values;
  roundToHalves(rounded.data(), rounded.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    ASSERT_EQ(std::bit_cast<std::uint32_t>(rounded[i]),
              std::bit_cast<std::uint32_t>(nearestHalf(values[i])))
        << "value " << i << ": " << values[i];
}

TEST(HalfArrays, EveryHalfGivesItsOwnBits) {
  std::vector<float> halves = everyHalf();
  halves.pop_back();  // 63487: a tail of seven
  std::vector<std::uint16_t> bits(halves.size());
  halvesToBits(halves.data(), halves.size(), bits.data());
  for (std::size_t i = 0; i < halves.size(); ++i)
    ASSERT_EQ(bits[i], exactHalfBits(halves[i])) << "half " << i << ": " << halves[i];
}

TEST(HalfArrays, EveryHalfsBitsGiveTheFloatHalfToFloatGives) {
  // All 65536 patterns, infinities and NaNs included, and a tail of seven.
  std::vector<std::uint16_t> bits(65536 + 7);
  for (std::size_t i = 0; i < bits.size(); ++i)
    bits[i] = std::uint16_t(i);
  std::vector<float> floats(bits.size() + 1, 12345.0f);
  bitsToFloats(bits.data(), bits.size(), floats.data());
  for (std::size_t i = 0; i < bits.size(); ++i) {
    const float expected = halfToFloat(bits[i]);
    if (std::isnan(expected))
      ASSERT_TRUE(std::isnan(floats[i])) << "bits " << bits[i];
    else
      ASSERT_EQ(std::bit_cast<std::uint32_t>(floats[i]), std::bit_cast<std::uint32_t>(expected))
          << "bits " << bits[i];
  }
  EXPECT_EQ(floats.back(), 12345.0f);  // nothing written beyond them
}

TEST(HalfArrays, PointsPackAsFourHalvesWithTheMaskLast) {
  const std::vector<float> halves = everyHalf();
  const std::size_t points = halves.size() / 3;  // 21162 points
  std::vector<std::uint8_t> valid(points);
  for (std::size_t i = 0; i < points; ++i)
    valid[i] = i % 5 == 2 ? 0 : 1;
  for (const bool masked : {false, true}) {
    SCOPED_TRACE(masked ? "masked" : "all valid");
    for (const std::size_t n : {points, std::size_t{1}, std::size_t{0}}) {
      std::vector<std::uint64_t> packed(n + 1, 0xdeadbeefu);
      packHalfPoints(halves.data(), masked ? valid.data() : nullptr, n, packed.data());
      for (std::size_t i = 0; i < n; ++i) {
        const float* p = &halves[3 * i];
        const std::uint64_t w = masked && valid[i] == 0 ? 0 : 0x3c00;  // the half 1.0
        const std::uint64_t expected = std::uint64_t(exactHalfBits(p[0])) |
                                       std::uint64_t(exactHalfBits(p[1])) << 16 |
                                       std::uint64_t(exactHalfBits(p[2])) << 32 | w << 48;
        ASSERT_EQ(packed[i], expected) << "point " << i;
      }
      EXPECT_EQ(packed[n], 0xdeadbeefu);  // nothing written beyond the points
    }
  }
}

}  // namespace
}  // namespace sandstorm
