#include "core/field/vector_field.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <iomanip>
#include <utility>

#include "core/field/field_range.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

// Trilinear interpolation reproduces any function linear in each coordinate
// exactly, so a linear field checks indexing, weights and bounds mapping.
glm::vec3 linear(const glm::vec3& p) {
  return {2.0f * p.x - p.y + 0.5f, p.z * 3.0f + 1.0f, -p.x + 0.25f * p.y + p.z};
}

VectorField linearField() {
  VectorField f(Box{{-1, 0, 2}, {3, 2, 4}}, {5, 3, 9});
  for (int k = 0; k < 9; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 5; ++i)
        f.at(i, j, k) = linear(f.pointPosition(i, j, k));
  return f;
}

// IEEE binary16 by hand: the nearest half to x (ties to even, as GPUs and
// F16C round), from its definition (11 significant bits; below 2^-14 a fixed
// step of 2^-24).
float halfByDefinition(float x) {
  const double a = std::abs(double(x));
  if (a == 0.0) return x;
  const int exponent = std::max(int(std::floor(std::log2(a))), -14);
  const double step = std::ldexp(1.0, exponent - 10);
  const double q = a / step, low = std::floor(q);
  const double n = q - low > 0.5 || (q - low == 0.5 && std::fmod(low, 2.0) == 1.0) ? low + 1 : low;
  return float(std::copysign(n * step, double(x)));
}

TEST(VectorField, HalfPrecisionRoundsToTheNearestHalfWithinAThousandthOfTheFastest) {
  VectorField f(Box{{0, 0, 0}, {1, 1, 1}}, {9, 7, 5});
  std::uint32_t state = 12345;
  const auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return float(state >> 8) / float(1u << 24);
  };
  for (glm::vec3& v : f.values())
    v = glm::vec3(next() - 0.5f, next() * 1e-6f, 40.0f * next() - 20.0f) * 1.7f;
  f.values()[3] = glm::vec3(1.0f, 0.5f, -2048.0f);  // exactly representable: kept
  // Ties: halfway between 1 and 1 + 2^-10 (to 1), between 1 + 2^-10 and
  // 1 + 2^-9 (to 1 + 2^-9), and between the two smallest subnormals' steps.
  f.values()[4] = glm::vec3(1.0f + 0x1p-11f, 1.0f + 3 * 0x1p-11f, -3 * 0x1p-25f);
  const VectorField before = f;
  EXPECT_FALSE(f.halfPrecision());
  f.roundToHalf();
  EXPECT_TRUE(f.halfPrecision());
  // The range of the rounded values is found while rounding, and is theirs.
  ASSERT_TRUE(f.rememberedRange());
  const FieldRange remembered = FieldRange::of(f);
  VectorField fresh = f;
  fresh.values();  // a change may follow: forgotten, found again from the values
  EXPECT_FALSE(fresh.rememberedRange());
  EXPECT_EQ(remembered, FieldRange::of(fresh));
  const float fastest = before.maxMagnitude();
  float worst = 0.0f;
  std::size_t changed = 0;
  for (std::size_t i = 0; i < f.pointCount(); ++i) {
    for (int c = 0; c < 3; ++c)
      ASSERT_EQ(f.values()[i][c], halfByDefinition(before.values()[i][c]))
          << i << "," << c << ": " << std::setprecision(12) << before.values()[i][c];
    worst = std::max(worst, glm::length(f.values()[i] - before.values()[i]));
    changed += f.values()[i] != before.values()[i];
  }
  EXPECT_LE(worst, 1e-3f * fastest);
  EXPECT_GT(changed, f.pointCount() / 2);
  EXPECT_EQ(f.values()[3], glm::vec3(1.0f, 0.5f, -2048.0f));
  EXPECT_EQ(f.values()[4], glm::vec3(1.0f, 1.0f + 0x1p-9f, -2 * 0x1p-24f));

  // Beyond what half holds: refused, nothing changed.
  VectorField big(Box{{0, 0, 0}, {1, 1, 1}}, {2, 2, 2});
  big.values()[5] = glm::vec3(0.1f, -70000.0f, 0.0f);
  EXPECT_THROW(big.roundToHalf(), Error);
  EXPECT_FALSE(big.halfPrecision());
  EXPECT_EQ(big.values()[5].x, 0.1f);
}

// A pair blended point by point and sampled (sampleBlended, the compute
// update's FieldPairBlend) is the grid of the blended points, built here from
// the definition (each component a + (b - a) * w, the nearest half of it
// for halves), sampled: bit for bit, at points all over the cells.
TEST(VectorField, ABlendedPairSamplesAsTheGridOfItsBlendedPoints) {
  const Box box{{-1, 0, 2}, {3, 2, 4}};
  const glm::ivec3 dims{5, 3, 9};
  VectorField a(box, dims), b(box, dims);
  std::uint32_t state = 777;
  const auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return float(state >> 8) / float(1u << 24) - 0.5f;
  };
  for (glm::vec3& v : a.values())
    v = glm::vec3(next(), next() * 3e-5f, 700.0f * next());
  for (glm::vec3& v : b.values())
    v = glm::vec3(next(), next() * 3e-5f, 700.0f * next());
  for (const bool halves : {false, true}) {
    SCOPED_TRACE(halves ? "halves" : "floats");
    if (halves) a.roundToHalf(), b.roundToHalf();
    // Read only from here: writing access forgets that the values are halves.
    const VectorField& ca = a;
    const VectorField& cb = b;
    ASSERT_EQ(ca.halfPrecision(), halves);
    for (const float w : {0.0f, 0.3f, 0.71f, 1.0f}) {
      VectorField blended(box, dims);
      for (std::size_t i = 0; i < blended.values().size(); ++i)
        for (int c = 0; c < 3; ++c) {
          const float x = ca.values()[i][c] + (cb.values()[i][c] - ca.values()[i][c]) * w;
          blended.values()[i][c] = halves ? halfByDefinition(x) : x;
        }
      for (int n = 0; n < 500; ++n) {
        const glm::vec3 p(1.0f + 2.2f * next(), 1.0f + 2.2f * next(), 3.0f + 2.2f * next());
        const glm::vec3 got = ca.sampleBlended(cb, w, p), want = std::as_const(blended).sample(p);
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(std::bit_cast<std::uint32_t>(got[c]), std::bit_cast<std::uint32_t>(want[c]))
              << "w " << w << " point " << n << " component " << c;
      }
    }
  }
  // Halves blended are rounded: the samples differ from blending the samples.
  const glm::vec3 p(0.37f, 1.21f, 3.3f);
  const VectorField& ca = a;
  const VectorField& cb = b;
  ASSERT_TRUE(ca.halfPrecision());
  EXPECT_NE(ca.sampleBlended(cb, 0.3f, p), ca.sample(p) + (cb.sample(p) - ca.sample(p)) * 0.3f);
}

TEST(VectorField, PointPositionsSpanTheBounds) {
  const VectorField f = linearField();
  EXPECT_EQ(f.pointPosition(0, 0, 0), glm::vec3(-1, 0, 2));
  EXPECT_EQ(f.pointPosition(4, 2, 8), glm::vec3(3, 2, 4));
  EXPECT_EQ(f.pointPosition(2, 1, 4), glm::vec3(1, 1, 3));
  EXPECT_EQ(f.index(1, 2, 3), 1u + 5u * (2u + 3u * 3u));  // x fastest
}

TEST(VectorField, TrilinearSamplingIsExactForLinearFields) {
  const VectorField f = linearField();
  for (const glm::vec3 p : {glm::vec3(0.3f, 1.7f, 2.9f), glm::vec3(-0.99f, 0.01f, 3.999f),
                            glm::vec3(2.5f, 0.5f, 2.25f), glm::vec3(1, 1, 3)}) {
    const glm::vec3 expected = linear(p), got = f.sample(p);
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(got[a], expected[a], 1e-5f) << "at " << p.x << "," << p.y;
  }
}

TEST(VectorField, SamplingClampsOutsideTheBounds) {
  const VectorField f = linearField();
  const glm::vec3 outside(10.0f, -5.0f, 3.0f);
  const glm::vec3 edge(3.0f, 0.0f, 3.0f);
  EXPECT_EQ(f.sample(outside), f.sample(edge));
}

TEST(VectorField, SingletonAxisIsConstantAlongIt) {
  VectorField f(Box{{0, 0, 5}, {1, 1, 5}}, {2, 2, 1});
  f.at(1, 1, 0) = glm::vec3(4, 0, 0);
  EXPECT_FLOAT_EQ(f.sample({0.5f, 0.5f, 100.0f}).x, 1.0f);
  EXPECT_FLOAT_EQ(f.sample({1.0f, 1.0f, -3.0f}).x, 4.0f);
}

TEST(VectorField, RejectsBadShapes) {
  EXPECT_THROW(VectorField(Box{{0, 0, 0}, {1, 1, 1}}, {0, 2, 2}), Error);
  EXPECT_THROW(VectorField(Box{{0, 0, 0}, {1, 1, 1}}, {-3, 2, 2}), Error);
  EXPECT_THROW(VectorField(Box{{0, 0, 0}, {1, 1, 1}}, {100000, 100000, 100000}), Error);
  EXPECT_THROW(VectorField(Box{{0, 0, 0}, {0, 1, 1}}, {2, 2, 2}), Error);  // empty extent
  EXPECT_THROW(VectorField(Box{{0, 0, 0}, {1, 1, 1}}, {2, 2, 2}, std::vector<glm::vec3>(7)), Error);
}

TEST(VectorField, ErrorsSayWhatWasExpected) {
  try {
    VectorField(Box{{0, 0, 0}, {1, 1, 1}}, {2, 0, 2});
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("dimension y is 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sandstorm
