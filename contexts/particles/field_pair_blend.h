// FieldPairBlend: a time-varying field's pair of grids blended point by point
// into one grid of its own, once a frame (shaders/field_blend.comp), for the
// compute update to sample one grid where it sampled two.
//
// Sampling both grids of a 256^3 series' pair and blending the samples cost
// the CAVE frame's update 2.5 ms on an H200 (4.15 against 1.65 ms steady:
// twice the memory for the L2 cache to serve); the blend pass reads each pair
// once, 3 x 134 MB for halves. The grid is the pair's layout (GpuField
// Buffer or HalfBuffer): a + (b - a) * weight, rounded to halves for halves,
// valid where both are. The CPU twin samples the same grid
// (VectorField::sampleBlended). It costs one more grid on the GPU.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/particles/gpu_field.h"

namespace sandstorm {

class FieldPairBlend {
 public:
  // Blends `first` and `second` (GpuFields in one buffer layout, their grids
  // sharing dims) with `weight` towards the second, unless this holds that
  // very blend already. Binds the pair at storage-buffer bindings 14 and 15
  // and the blend at 13. Throws Error when the GPU has no memory for it.
  void blend(const GpuField& first, const GpuField& second, float weight);
  // The blended grid's buffer (0 before the first blend).
  std::uint32_t buffer() const { return grid_.id(); }
  // Forgets the blend (the pair changed), keeping the buffer.
  void forget() { first_.reset(), second_.reset(); }
  // Gives the grid's GPU memory back and lets go of the pair (no pair to
  // blend any more: a steady field, or the pair sampled otherwise).
  void release() {
    forget();
    grid_.reset();
    bytes_ = 0;
  }

 private:
  gl::Buffer grid_;
  std::size_t bytes_ = 0;
  GpuField::Storage storage_ = GpuField::Storage::Buffer;
  std::unique_ptr<gl::Program> program_;  // for storage_
  // What grid_ holds: the pair's fields and the weight.
  std::shared_ptr<const VectorField> first_, second_;
  float weight_ = 0.0f;
};

}  // namespace sandstorm
