// Half floats by the million: a grid's components rounded to halves
// (VectorField::roundToHalf, on a series' reader threads) and a rounded
// grid's halves packed for the GPU (GpuField's uploads, on a worker while
// the walls draw). One component at a time (core/util/half_float.h) these
// take several nanoseconds each, and a 256^3 step has 50 million; where the
// CPU has x86's F16C conversions (every x86-64 CPU since 2012) they go eight
// or four at a time, with the same results: F16C rounds to nearest, ties to
// even, as nearestHalf does, and a value that is a half converts exactly.
#pragma once

#include <cstddef>
#include <cstdint>

namespace sandstorm {

// Each of n floats replaced by the half nearest to it, as a float. Every
// |value| must be at most 65504 (VectorField checks first).
void roundToHalves(float* values, std::size_t n);

// n floats that are halves already (roundToHalves' results) as their bits.
void halvesToBits(const float* values, std::size_t n, std::uint16_t* out);

// n halves' bits as the floats they stand for (exactly, as halfToFloat).
void bitsToFloats(const std::uint16_t* bits, std::size_t n, float* out);

// Points of three floats that are halves already (x, y, z, x fastest) as
// four halves each, one 64-bit word a point: x, y, z from the lowest bits
// up, then 1 where valid[i] is not 0 (or valid is null) and 0 where it is:
// GpuField's HalfRgba point.
void packHalfPoints(const float* xyz, const std::uint8_t* valid, std::size_t points,
                    std::uint64_t* out);

}  // namespace sandstorm
