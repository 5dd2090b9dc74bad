// Half floats (IEEE 754 binary16) on the CPU, rounding to nearest, ties to
// even, as the GPU's own conversions and x86's F16C do.
//
// field.precision = "half" rounds every vector component of a grid with
// nearestHalf (VectorField::roundToHalf) and uploads the results' bits
// (halfBits: exact for a value that is already a half). A 256^3 grid holds
// 50 million components, and a series rounds one such grid per step on its
// reader threads: these are a few integer operations each, with no table and
// no loop, where glm::packHalf takes several branches per component.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>

namespace sandstorm {

// The half nearest to x, as a float (ties to even). |x| must be at most
// 65504 (the largest half; callers check first): larger values are not
// rounded to infinity here.
inline float nearestHalf(float x) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(x);
  const std::uint32_t sign = bits & 0x80000000u;
  const std::uint32_t magnitude = bits ^ sign;
  std::uint32_t rounded;
  if (magnitude < 0x38800000u) {
    // Below 2^-14 halves are spaced 2^-24 apart: adding 0.5 (whose float
    // spacing is 2^-24) rounds to that grid, ties to even, and subtracting
    // it again is exact.
    rounded = std::bit_cast<std::uint32_t>((std::bit_cast<float>(magnitude) + 0.5f) - 0.5f);
  } else {
    // 11 significant bits: drop 13 of the float's 24, adding just under half
    // of the dropped unit, plus one when the kept part is odd (ties to even).
    rounded = (magnitude + 0x0fffu + ((magnitude >> 13) & 1u)) & ~0x1fffu;
  }
  return std::bit_cast<float>(rounded | sign);
}

// The bits of the half nearest to x (ties to even); |x| at most 65504.
inline std::uint16_t halfBits(float x) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(nearestHalf(x));
  const std::uint32_t sign = (bits >> 16) & 0x8000u;
  const std::uint32_t magnitude = bits & 0x7fffffffu;
  if (magnitude < 0x38800000u)  // a subnormal half (or zero): a multiple of 2^-24
    return std::uint16_t(sign | std::uint32_t(std::bit_cast<float>(magnitude) * 16777216.0f));
  return std::uint16_t(sign | ((magnitude - 0x38000000u) >> 13));
}

// The bits of x, which must already be a finite half (a value nearestHalf
// returned; VectorField::roundToHalf's grids): no rounding and no branch,
// so that an upload's loop over millions of them vectorizes.
inline std::uint16_t exactHalfBits(float x) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(x);
  const std::uint32_t sign = (bits >> 16) & 0x8000u;
  const std::uint32_t magnitude = bits & 0x7fffffffu;
  const std::uint32_t normal = (magnitude - 0x38000000u) >> 13;
  // Below 2^-14 a multiple of 2^-24; the min keeps the product in range
  // for the values that take the other side.
  const std::uint32_t subnormal = std::uint32_t(
      std::int32_t(std::min(std::bit_cast<float>(magnitude), 6.103515625e-05f) * 16777216.0f));
  return std::uint16_t(sign | (magnitude < 0x38800000u ? subnormal : normal));
}

// The float a half's bits stand for (every half is a float exactly).
inline float halfToFloat(std::uint16_t h) {
  const std::uint32_t sign = std::uint32_t(h & 0x8000u) << 16;
  const std::uint32_t exponent = (h >> 10) & 0x1fu;
  const std::uint32_t mantissa = h & 0x3ffu;
  if (exponent == 0)  // zero or subnormal: mantissa * 2^-24
    return std::bit_cast<float>(std::bit_cast<std::uint32_t>(float(mantissa) * 5.9604645e-8f) |
                                sign);
  if (exponent == 31) return std::bit_cast<float>(sign | 0x7f800000u | (mantissa << 13));
  return std::bit_cast<float>(sign | ((exponent + 112u) << 23) | (mantissa << 13));
}

}  // namespace sandstorm
