// Reservoir<T>: a uniform sample of at most `capacity` of the values offered
// (Vitter's algorithm R), so statistics over a run of any length take bounded
// memory: a CAVE left running for days at 90 fps offers millions of frames.
// Until `capacity` values have come, it holds them all, in order. The choice
// is deterministic (a counter-based generator), so a run's statistics repeat.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sandstorm {

template <class T>
class Reservoir {
 public:
  explicit Reservoir(std::size_t capacity) : capacity_(capacity) {}

  void offer(const T& value) {
    ++seen_;
    if (values_.size() < capacity_) {
      values_.push_back(value);
      return;
    }
    // Keep the n-th value with probability capacity / n, in a uniform slot.
    const std::uint64_t slot = next() % seen_;
    if (slot < capacity_) values_[std::size_t(slot)] = value;
  }

  const std::vector<T>& values() const { return values_; }
  std::uint64_t seen() const { return seen_; }
  std::size_t capacity() const { return capacity_; }

 private:
  // splitmix64 of the count: uniform enough for sampling, and repeatable.
  std::uint64_t next() const {
    std::uint64_t z = seen_ * 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  std::size_t capacity_;
  std::uint64_t seen_ = 0;
  std::vector<T> values_;
};

}  // namespace sandstorm
