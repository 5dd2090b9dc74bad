#include "core/field/sparse_leaf_array.h"

#define PNANOVDB_C
#include <nanovdb/PNanoVDB.h>

namespace sandstorm {

SparseLeafArray sparseLeafArray(const SparseField& field) {
  // PNanoVDB's reader takes a mutable pointer; it only reads.
  const std::span<const std::uint32_t> words = field.words();
  const pnanovdb_buf_t buf =
      pnanovdb_make_buf(const_cast<std::uint32_t*>(words.data()), words.size());
  const pnanovdb_grid_handle_t grid = {pnanovdb_address_null()};
  const pnanovdb_tree_handle_t tree = pnanovdb_grid_get_tree(buf, grid);
  return {PNANOVDB_GRID_SIZE + pnanovdb_tree_get_node_offset_leaf(buf, tree),
          pnanovdb_tree_get_node_count_leaf(buf, tree),
          PNANOVDB_GRID_TYPE_GET(PNANOVDB_GRID_TYPE_VEC3F, leaf_size)};
}

}  // namespace sandstorm
