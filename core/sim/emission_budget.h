// EmissionBudget: how many newborn particles an update may add, decided before
// the update runs, from counts the GPU reported two updates ago.
//
// Soft limit L = min(Maximum, capacity). Update u emits E(u) particles and keeps
// S(u) survivors of its input, so count(u) = E(u) + S(u). Survivors never exceed
// the input, so
//   S(u) <= count(u-1) = E(u-1) + S(u-1) <= E(u-1) + count(u-2),
// and emitting at most L - (count(u-2) + E(u-1)) keeps count(u) <= L without
// waiting for the GPU: count(u-2) was read back one whole frame after it was
// produced. Every context, and the CPU reference, computes the same numbers.
// The price: the live count settles a frame or two of emission below Maximum.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sandstorm {

class EmissionBudget {
 public:
  // The particles that update u may add, given the desired per-emitter counts,
  // earlier emitters first. `count2` is count(u-2), the caller's readback.
  std::vector<std::uint32_t> allocate(const std::vector<std::uint32_t>& desired, std::size_t limit,
                                      std::size_t count2) const;

  // Records update u's emission (call once per update, after allocate()).
  void recordEmitted(std::uint32_t emitted) { previousEmitted_ = emitted; }
  void reset() { previousEmitted_ = 0; }
  std::uint32_t previousEmitted() const { return previousEmitted_; }

 private:
  std::uint32_t previousEmitted_ = 0;  // E(u-1)
};

}  // namespace sandstorm
