// SparseLeafMemory: each particle record's remembered leaf of a sparse grid
// (shaders/field_sparse.glsl's gSparseLeaf), carried from one update to the
// next beside the records: the update reads a survivor's at its input record
// (binding 9) and writes it at its output record (binding 10), so a particle
// that stays in its 8^3 leaf samples it without walking NanoVDB's tree. Two
// buffers of one 32-bit index a record take turns as the record sets do.
// Any content is safe (the shader checks a leaf before it uses it), so the
// newborn's slots keep whatever they held. Needs its GL context current.
#pragma once

#include <array>
#include <cstddef>

#include "contexts/gl/objects.h"

namespace sandstorm {

class SparseLeafMemory {
 public:
  // Binds the buffer of input set `in` at 9 and the other at 10, first
  // making them `capacity` records long (none remembered) where they are
  // shorter.
  void bind(int in, std::size_t capacity);

 private:
  std::array<gl::Buffer, 2> leaves_;
  std::size_t capacity_ = 0;
};

}  // namespace sandstorm
