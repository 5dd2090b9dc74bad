// MoleculeGridGpu: the molecules' repulsion grid on the GPU, built each
// update from the input molecules (the twin of MoleculeGrid in
// core/molecules/molecule_grid.h):
//   1. molecule_grid_keys.comp: each molecule's centre, its cell's key
//      (a hash into a table of a power of two no smaller than the capacity)
//      and its index;
//   2. GpuRadixSort sorts the keys and indices, stably, so a key's molecules
//      stay in index order;
//   3. molecule_grid_starts.comp: where each key's run starts.
// The update then walks the 27 cells around each molecule (molecule_grid.glsl).
// Expects the sim and molecule blocks bound; needs its GL context current.
#pragma once

#include <cstdint>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/sort/gpu_radix_sort.h"

namespace sandstorm {

class MoleculeGridGpu {
 public:
  MoleculeGridGpu();

  // The table's size - 1 for `capacity` molecules (the molecule block's grid.x).
  static std::uint32_t tableMask(std::size_t capacity);

  // Builds the grid of the input set `inSet` (positions in `positions`; the
  // control block bound at binding 4 holds its count) and binds it (7..10).
  void build(std::size_t capacity, std::uint32_t positions, int inSet, std::uint32_t control,
             std::uint32_t countOffset);

 private:
  gl::Program keys_, starts_;
  GpuRadixSort sort_;
  gl::Buffer centres_, sortKeys_, sortValues_, table_;
  std::size_t capacity_ = 0;
};

}  // namespace sandstorm
