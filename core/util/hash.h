// FNV-1a, 64 bit: a fingerprint of particle buffers, to show that two
// contexts (threads, processes, MPI ranks) hold bitwise the same particles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace sandstorm {

inline std::uint64_t fnv1a64(std::span<const std::byte> bytes,
                             std::uint64_t hash = 14695981039346656037ull) {
  for (const std::byte b : bytes) {
    hash ^= std::uint64_t(b);
    hash *= 1099511628211ull;
  }
  return hash;
}

template <class T>
std::uint64_t hashOf(std::span<const T> items) {
  return fnv1a64(std::as_bytes(items));
}

}  // namespace sandstorm
