// Half floats against their definition (IEEE 754 binary16): 11 significant
// bits from 2^-14 up, a fixed step of 2^-24 below; a value between two halves
// goes to the nearer, a tie to the one whose last bit is 0.
#include "core/util/half_float.h"

#include <bit>
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

namespace sandstorm {
namespace {

// The value of a finite half's bits, from the definition.
double halfValue(std::uint16_t h) {
  const int exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
  const double magnitude = exponent == 0 ? std::ldexp(double(mantissa), -24)
                                         : std::ldexp(1024.0 + mantissa, exponent - 25);
  return (h & 0x8000) ? -magnitude : magnitude;
}

TEST(HalfFloat, EveryFiniteHalfConvertsBothWaysExactly) {
  int checked = 0;
  for (std::uint32_t h = 0; h < 65536; ++h) {
    if (((h >> 10) & 0x1f) == 0x1f) continue;  // infinities and NaNs
    const float value = halfToFloat(std::uint16_t(h));
    ASSERT_EQ(double(value), halfValue(std::uint16_t(h))) << std::hex << h;
    ASSERT_EQ(std::signbit(value), (h & 0x8000) != 0) << std::hex << h;
    ASSERT_EQ(halfBits(value), h) << std::hex << h;
    ASSERT_EQ(exactHalfBits(value), h) << std::hex << h;
    ASSERT_EQ(std::bit_cast<std::uint32_t>(nearestHalf(value)),
              std::bit_cast<std::uint32_t>(value));
    ++checked;
  }
  EXPECT_EQ(checked, 63488);  // 2 x 31 exponents x 1024
  EXPECT_TRUE(std::isinf(halfToFloat(0x7c00)));
  EXPECT_TRUE(std::isnan(halfToFloat(0x7e01)));
}

TEST(HalfFloat, BetweenTwoHalvesTheNearerWinsAndATieGoesToTheEvenOne) {
  // Every pair of neighbouring non-negative halves below 65504, and the
  // floats at, just below and just above their midpoint.
  for (std::uint16_t low = 0; low < 0x7bff; ++low) {
    const double a = halfValue(low), b = halfValue(std::uint16_t(low + 1));
    const float mid = float((a + b) / 2);  // exact: a float has 13 more bits
    ASSERT_EQ(double(mid), (a + b) / 2);
    const std::uint16_t even = (low & 1) ? std::uint16_t(low + 1) : low;
    const float below = std::nextafter(mid, 0.0f), above = std::nextafter(mid, 1e9f);
    for (const float sign : {1.0f, -1.0f}) {
      const std::uint16_t s = sign < 0 ? 0x8000 : 0;
      ASSERT_EQ(halfBits(sign * mid), std::uint16_t(even | s)) << low;
      ASSERT_EQ(halfBits(sign * below), std::uint16_t(low | s)) << low;
      ASSERT_EQ(halfBits(sign * above), std::uint16_t((low + 1) | s)) << low;
      ASSERT_EQ(double(nearestHalf(sign * mid)), double(sign) * halfValue(even)) << low;
      ASSERT_EQ(double(nearestHalf(sign * above)), double(sign) * b) << low;
    }
  }
  // Below the smallest half's half: zero, keeping the sign.
  EXPECT_EQ(halfBits(2.9e-8f), 0);
  EXPECT_EQ(halfBits(-2.9e-8f), 0x8000);
  EXPECT_TRUE(std::signbit(nearestHalf(-1e-30f)));
  EXPECT_EQ(halfBits(65504.0f), 0x7bff);
}

}  // namespace
}  // namespace sandstorm
