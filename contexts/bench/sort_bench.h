// sortMs(): GpuRadixSort's time for `keys` random 32-bit keys with values
// (the median GPU milliseconds of `repeats` sorts, each of fresh keys), and
// the memory traffic one sort moves: eight passes, each reading the keys for
// the histogram and the keys and values for the scatter and writing both
// again (20 bytes a key a pass). Needs a current GL context.
#pragma once

#include <cstddef>

namespace sandstorm::bench {

constexpr double kSortBytesPerKey = 8.0 * 20.0;

double sortMs(std::size_t keys, int repeats);

}  // namespace sandstorm::bench
