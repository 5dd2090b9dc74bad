// GpuRadixSort: a stable least-significant-digit radix sort of 32-bit keys
// carrying 32-bit values, in compute shaders (the Mali sample's scheme with a
// wider digit): eight passes of 4 bits, each
//   1. radix_histogram.comp: every block of 1024 keys counts its digits into
//      a digit-major table (digit d of block b at d * blocks + b);
//   2. radix_scan.comp: one exclusive prefix sum over that table, so entry
//      (d, b) is where block b's keys of digit d start in the output;
//   3. radix_scatter.comp: each block ranks its keys within their digit in
//      their input order (a prefix sum in shared memory) and writes them
//      there, so keys of equal digits keep their order: the sort is stable.
// Keys and values are sorted in place, through scratch buffers (eight passes
// end where they began). The count may be the GPU's own (a live-particle
// count in a buffer), so nothing waits for the CPU; the dispatch covers the
// capacity and blocks past the count do nothing.
//
// Needs its GL context current for every call.
#pragma once

#include <cstddef>
#include <cstdint>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"

namespace sandstorm {

class GpuRadixSort {
 public:
  static constexpr std::uint32_t kBlock = 1024;  // keys a workgroup handles
  static constexpr int kDigitBits = 4;

  GpuRadixSort();

  // Sorts the first `count` keys of `keys` (GL buffer names, uint32 each) and
  // the values beside them; both hold at least `count` entries.
  void sort(std::uint32_t keys, std::uint32_t values, std::uint32_t count);
  // The same for the count the GPU holds as a uint at `countOffset` bytes into
  // `countBuffer`, at most `capacity` (entries past it are left alone).
  void sortCounted(std::uint32_t keys, std::uint32_t values, std::size_t capacity,
                   std::uint32_t countBuffer, std::size_t countOffset);

 private:
  void reserve(std::size_t capacity);
  void run(std::uint32_t keys, std::uint32_t values);

  gl::Program histogram_, scan_, scatter_;
  gl::Buffer scratchKeys_, scratchValues_, table_, count_;
  std::size_t capacity_ = 0;
  std::uint32_t blocks_ = 0;
};

}  // namespace sandstorm
