// Buffer capacity: the hard limit on particles, which grows when the soft
// limit (sim.maximum) is raised above it (the thesis's future-work item on
// dynamic buffers). Every context and the CPU reference grow at the same
// frame to the same size, so they stay identical.
#pragma once

#include <algorithm>
#include <cstddef>

namespace sandstorm {

// Capacity needed for `maximum` live particles: unchanged while it suffices,
// else `maximum` rounded up to a multiple of 4096, never above `limit`.
inline std::size_t grownCapacity(std::size_t current, int maximum, std::size_t limit) {
  const std::size_t wanted = std::size_t(std::max(maximum, 0));
  if (wanted <= current) return current;
  const std::size_t rounded = (wanted + 4095) / 4096 * 4096;
  return std::max(current, std::min(rounded, limit));
}

}  // namespace sandstorm
