// The control block the compute updates of particles and molecules share
// (shaders/particle_control.glsl: its twin), and UpdateCounts, the live
// counts those updates leave, read by the CPU an update or two late.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "contexts/gl/objects.h"

namespace sandstorm {

// Byte offsets in the control block: two counts (a buffer set each), the
// scan's ticket and tiles, the indirect dispatch, two indirect draws. The
// updates' sources take them with `using namespace update_control;`.
namespace update_control {
inline constexpr std::ptrdiff_t kCountOffset = 0;
inline constexpr std::ptrdiff_t kDispatchOffset = 16;
inline constexpr std::ptrdiff_t kDrawOffset = 32;
inline constexpr std::ptrdiff_t kControlSize = 64;
// A particle's (or molecule member's) two records: position and life, velocity and kind.
inline constexpr std::ptrdiff_t kRecord = 16;
}  // namespace update_control

// The live count after each of the last kSlots updates, copied on the GPU
// from the control block into a persistently mapped buffer with a fence
// each: reading the count an update late rarely waits, and never reads the
// control block itself (record_readback.h says why).
class UpdateCounts {
 public:
  static constexpr int kSlots = 3;

  // `owner` names it in errors ("ParticleComputeUpdate").
  explicit UpdateCounts(const char* owner);

  // After update `update` is submitted: copies the count at byte `offset` of
  // the control block `control`.
  void record(std::uint64_t update, std::uint32_t control, std::ptrdiff_t offset);
  // The count update `update` left (one of the last kSlots recorded); waits
  // for its copy if the GPU has not made it yet.
  std::size_t after(std::uint64_t update) const;

 private:
  gl::Buffer buffer_;
  const std::uint32_t* map_ = nullptr;
  std::array<gl::Sync, kSlots> fences_;
};

}  // namespace sandstorm
