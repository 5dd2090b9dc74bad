#include "core/util/half_arrays.h"

#include "core/util/half_float.h"

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#include <immintrin.h>
#define SANDSTORM_F16C 1
#endif

namespace sandstorm {
namespace {

void roundScalar(float* values, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    values[i] = nearestHalf(values[i]);
}

void bitsScalar(const float* values, std::size_t n, std::uint16_t* out) {
  for (std::size_t i = 0; i < n; ++i)
    out[i] = exactHalfBits(values[i]);
}

void floatsScalar(const std::uint16_t* bits, std::size_t n, float* out) {
  for (std::size_t i = 0; i < n; ++i)
    out[i] = halfToFloat(bits[i]);
}

std::uint64_t packScalar(const float* xyz, bool valid) {
  static const std::uint64_t one = std::uint64_t(halfBits(1.0f)) << 48;
  return std::uint64_t(exactHalfBits(xyz[0])) | std::uint64_t(exactHalfBits(xyz[1])) << 16 |
         std::uint64_t(exactHalfBits(xyz[2])) << 32 | (valid ? one : 0);
}

#ifdef SANDSTORM_F16C
// F16C's instructions, and AVX's registers with the system saving them
// (XCR0's SSE and AVX bits): CPUID asked directly, as GCC's and Clang's
// __builtin_cpu_supports do not both know "f16c".
bool hasF16c() {
  static const bool has = [] {
    unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
    if (!__get_cpuid(1, &eax, &ebx, &ecx, &edx)) return false;
    if ((ecx & bit_OSXSAVE) == 0 || (ecx & bit_AVX) == 0 || (ecx & bit_F16C) == 0) return false;
    unsigned low = 0, high = 0;
    __asm__("xgetbv" : "=a"(low), "=d"(high) : "c"(0));
    return (low & 6u) == 6u;
  }();
  return has;
}

__attribute__((target("avx,f16c"))) void roundF16c(float* values, std::size_t n) {
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    const __m128i h = _mm256_cvtps_ph(_mm256_loadu_ps(values + i), _MM_FROUND_TO_NEAREST_INT);
    _mm256_storeu_ps(values + i, _mm256_cvtph_ps(h));
  }
  roundScalar(values + i, n - i);
}

__attribute__((target("avx,f16c"))) void bitsF16c(const float* values, std::size_t n,
                                                  std::uint16_t* out) {
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8)
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i),
                     _mm256_cvtps_ph(_mm256_loadu_ps(values + i), _MM_FROUND_TO_NEAREST_INT));
  bitsScalar(values + i, n - i, out + i);
}

__attribute__((target("avx,f16c"))) void floatsF16c(const std::uint16_t* bits, std::size_t n,
                                                    float* out) {
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8)
    _mm256_storeu_ps(out + i,
                     _mm256_cvtph_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(bits + i))));
  floatsScalar(bits + i, n - i, out + i);
}

__attribute__((target("avx,f16c,sse4.1"))) void packF16c(const float* xyz,
                                                         const std::uint8_t* valid,
                                                         std::size_t points, std::uint64_t* out) {
  // A point's four floats: its x, y, z and the next point's x (or, for the
  // last point, no further load), w replaced by 1 or 0, then four halves.
  std::size_t i = 0;
  for (; i + 1 < points; ++i) {
    const float w = valid && valid[i] == 0 ? 0.0f : 1.0f;
    const __m128 point = _mm_blend_ps(_mm_loadu_ps(xyz + 3 * i), _mm_set1_ps(w), 0x8);
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out + i),
                     _mm_cvtps_ph(point, _MM_FROUND_TO_NEAREST_INT));
  }
  for (; i < points; ++i)
    out[i] = packScalar(xyz + 3 * i, !valid || valid[i] != 0);
}
#endif

}  // namespace

void roundToHalves(float* values, std::size_t n) {
#ifdef SANDSTORM_F16C
  if (hasF16c()) return roundF16c(values, n);
#endif
  roundScalar(values, n);
}

void halvesToBits(const float* values, std::size_t n, std::uint16_t* out) {
#ifdef SANDSTORM_F16C
  if (hasF16c()) return bitsF16c(values, n, out);
#endif
  bitsScalar(values, n, out);
}

void bitsToFloats(const std::uint16_t* bits, std::size_t n, float* out) {
#ifdef SANDSTORM_F16C
  if (hasF16c()) return floatsF16c(bits, n, out);
#endif
  floatsScalar(bits, n, out);
}

void packHalfPoints(const float* xyz, const std::uint8_t* valid, std::size_t points,
                    std::uint64_t* out) {
#ifdef SANDSTORM_F16C
  if (hasF16c()) return packF16c(xyz, valid, points, out);
#endif
  for (std::size_t i = 0; i < points; ++i)
    out[i] = packScalar(xyz + 3 * i, !valid || valid[i] != 0);
}

}  // namespace sandstorm
