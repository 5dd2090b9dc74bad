// SparseLeafArray: where a SparseField's leaves lie in its words. NanoVDB
// keeps a grid's 8^3 leaves in one array; the GPU remembers the leaf a
// particle's last sample lay in by its index there and reads the next cell in
// it without walking the tree (shaders/field_sparse.glsl). SparseField's
// constructor checks that each leaf's box names the voxels the tree finds in
// it, so a remembered leaf reads the values the walk would.
#pragma once

#include <cstdint>

#include "core/field/sparse_field.h"

namespace sandstorm {

struct SparseLeafArray {
  std::uint64_t begin = 0;  // the first leaf's byte in the words
  std::uint64_t count = 0;
  std::uint32_t bytes = 0;  // a leaf's
};

SparseLeafArray sparseLeafArray(const SparseField& field);

}  // namespace sandstorm
