#include "core/field/sparse_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/util/error.h"

// NanoVDB's reader for C, GLSL and HLSL: the same code the GPU runs
// (shaders/field_sparse.glsl), here with 64-bit addresses.
#define PNANOVDB_C
#include <nanovdb/PNanoVDB.h>

namespace sandstorm {
namespace {

constexpr pnanovdb_grid_type_t kType = PNANOVDB_GRID_TYPE_VEC3F;

pnanovdb_buf_t bufferOf(const std::vector<std::uint32_t>& words) {
  // PNanoVDB's reader takes a mutable pointer; it only reads.
  return pnanovdb_make_buf(const_cast<std::uint32_t*>(words.data()), words.size());
}

glm::vec3 readVec3(pnanovdb_buf_t buf, pnanovdb_address_t a) {
  return glm::vec3(pnanovdb_read_float(buf, a),
                   pnanovdb_read_float(buf, pnanovdb_address_offset(a, 4)),
                   pnanovdb_read_float(buf, pnanovdb_address_offset(a, 8)));
}

pnanovdb_root_handle_t rootOf(pnanovdb_buf_t buf) {
  const pnanovdb_grid_handle_t grid = {pnanovdb_address_null()};
  return pnanovdb_tree_get_root(buf, pnanovdb_grid_get_tree(buf, grid));
}

// The node arrays NanoVDB lays out one after another: where each begins and
// how many nodes it holds, checked against the buffer.
struct NodeArray {
  std::uint64_t begin = 0, count = 0, size = 0;
  bool holds(std::uint64_t address) const {
    return address >= begin && address < begin + count * size && (address - begin) % size == 0;
  }
};

}  // namespace

SparseField::SparseField(std::vector<std::uint32_t> words, const std::string& source)
    : words_(std::move(words)) {
  const std::uint64_t bytes = std::uint64_t(words_.size()) * 4;
  const auto fail = [&](const std::string& what) {
    throw Error(concat(source, ": not a sparse vector grid NanoVDB can read: ", what));
  };
  if (bytes < PNANOVDB_GRID_SIZE + PNANOVDB_TREE_SIZE)
    fail(concat(bytes, " bytes, fewer than a grid's header and tree (",
                PNANOVDB_GRID_SIZE + PNANOVDB_TREE_SIZE, ")"));
  const pnanovdb_buf_t buf = bufferOf(words_);
  const pnanovdb_grid_handle_t grid = {pnanovdb_address_null()};
  if (pnanovdb_grid_get_magic(buf, grid) != PNANOVDB_MAGIC_NUMBER) fail("no NanoVDB magic number");
  const std::uint32_t major = pnanovdb_version_get_major(pnanovdb_grid_get_version(buf, grid));
  if (major != PNANOVDB_MAJOR_VERSION_NUMBER)
    fail(concat("NanoVDB version ", major, "; expected ", PNANOVDB_MAJOR_VERSION_NUMBER));
  if (pnanovdb_grid_get_grid_type(buf, grid) != kType)
    fail(concat("value type ", pnanovdb_grid_get_grid_type(buf, grid), "; expected Vec3f (", kType,
                ")"));
  const std::uint64_t gridBytes = pnanovdb_grid_get_grid_size(buf, grid);
  if (gridBytes > bytes || gridBytes < PNANOVDB_GRID_SIZE + PNANOVDB_TREE_SIZE)
    fail(concat("the grid claims ", gridBytes, " bytes; the buffer holds ", bytes));
  // GLSL reads the buffer with 32-bit byte addresses.
  if (gridBytes > std::numeric_limits<std::uint32_t>::max())
    fail(concat(gridBytes, " bytes; a grid on the GPU holds at most 4 GiB"));

  // Axis-aligned: a diagonal, positive scale.
  const pnanovdb_map_handle_t map = pnanovdb_grid_get_map(buf, grid);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const double m = pnanovdb_map_get_matd(buf, map, std::uint32_t(3 * r + c));
      if (r == c ? !(m > 0.0 && std::isfinite(m)) : m != 0.0)
        throw Error(concat(source,
                           ": a sparse grid must be axis-aligned with a positive voxel size (its "
                           "transform's matrix has ",
                           m, " at row ", r, ", column ", c,
                           "); load it densely instead (field.storage = \"dense\")"));
    }
  for (int a = 0; a < 3; ++a) {
    voxelSize_[a] = float(pnanovdb_map_get_matd(buf, map, std::uint32_t(4 * a)));
    origin_[a] = float(pnanovdb_map_get_vecd(buf, map, std::uint32_t(a)));
    indexScale_[a] = 1.0f / voxelSize_[a];
  }
  if (!std::isfinite(origin_.x + origin_.y + origin_.z))
    fail("the transform's translation is not finite");

  // Every node array and the root's tiles inside the grid, and every child a
  // node names one of the next level's nodes: then no read strays.
  const pnanovdb_tree_handle_t tree = pnanovdb_grid_get_tree(buf, grid);
  const std::uint64_t treeAt = PNANOVDB_GRID_SIZE;
  const auto array = [&](std::uint64_t offset, std::uint64_t count, std::uint32_t size) {
    NodeArray a{treeAt + offset, count, size};
    if (count > 0 && (offset == 0 || a.begin > gridBytes || count > (gridBytes - a.begin) / size))
      fail(concat(count, " nodes of ", size, " bytes at byte ", a.begin, " pass the grid's end (",
                  gridBytes, ")"));
    return a;
  };
  const NodeArray leaves =
      array(pnanovdb_tree_get_node_offset_leaf(buf, tree),
            pnanovdb_tree_get_node_count_leaf(buf, tree), PNANOVDB_GRID_TYPE_GET(kType, leaf_size));
  const NodeArray lowers = array(pnanovdb_tree_get_node_offset_lower(buf, tree),
                                 pnanovdb_tree_get_node_count_lower(buf, tree),
                                 PNANOVDB_GRID_TYPE_GET(kType, lower_size));
  const NodeArray uppers = array(pnanovdb_tree_get_node_offset_upper(buf, tree),
                                 pnanovdb_tree_get_node_count_upper(buf, tree),
                                 PNANOVDB_GRID_TYPE_GET(kType, upper_size));
  const std::uint64_t rootAt = treeAt + pnanovdb_tree_get_node_offset_root(buf, tree);
  if (rootAt + PNANOVDB_GRID_TYPE_GET(kType, root_size) > gridBytes)
    fail(concat("the root node at byte ", rootAt, " passes the grid's end"));
  const pnanovdb_root_handle_t root = rootOf(buf);
  const std::uint64_t tiles = pnanovdb_root_get_tile_count(buf, root);
  if (tiles > (gridBytes - rootAt - PNANOVDB_GRID_TYPE_GET(kType, root_size)) /
                  PNANOVDB_GRID_TYPE_GET(kType, root_tile_size))
    fail(concat("the root's ", tiles, " tiles pass the grid's end"));
  const auto child = [&](const NodeArray& next, std::uint64_t at, std::int64_t offset,
                         const char* what) {
    const std::uint64_t address = at + std::uint64_t(offset);
    if (!next.holds(address))
      fail(concat("a ", what, " at byte ", at, " names a child at byte ", address,
                  ", not a node of the level below"));
  };
  for (std::uint32_t n = 0; n < tiles; ++n) {
    const pnanovdb_root_tile_handle_t tile = pnanovdb_root_get_tile(kType, root, n);
    const std::int64_t offset = pnanovdb_root_tile_get_child(buf, tile);
    if (offset != 0) child(uppers, rootAt, offset, "root tile");
  }
  for (std::uint64_t u = 0; u < uppers.count; ++u) {
    const pnanovdb_upper_handle_t node = {{uppers.begin + u * uppers.size}};
    for (std::uint32_t n = 0; n < 32768; ++n)
      if (pnanovdb_upper_get_child_mask(buf, node, n))
        child(lowers, node.address.byte_offset, pnanovdb_upper_get_table_child(kType, buf, node, n),
              "upper node");
  }
  for (std::uint64_t l = 0; l < lowers.count; ++l) {
    const pnanovdb_lower_handle_t node = {{lowers.begin + l * lowers.size}};
    for (std::uint32_t n = 0; n < 4096; ++n)
      if (pnanovdb_lower_get_child_mask(buf, node, n))
        child(leaves, node.address.byte_offset, pnanovdb_lower_get_table_child(kType, buf, node, n),
              "lower node");
  }

  const pnanovdb_coord_t lo = pnanovdb_root_get_bbox_min(buf, root);
  const pnanovdb_coord_t hi = pnanovdb_root_get_bbox_max(buf, root);
  indexMin_ = glm::ivec3(lo.x, lo.y, lo.z);
  indexMax_ = glm::ivec3(hi.x, hi.y, hi.z);
  forEachActive([&](const glm::vec3&, std::uint64_t count) { activeVoxels_ += count; });
  if (activeVoxels_ == 0 || glm::any(glm::greaterThan(indexMin_, indexMax_)))
    fail("it has no active voxels");
  // Indices in float keep sample()'s arithmetic exact and within int's range.
  constexpr int kMaxIndex = 1 << 24;
  if (glm::any(glm::lessThan(indexMin_, glm::ivec3(-kMaxIndex))) ||
      glm::any(glm::greaterThan(indexMax_, glm::ivec3(kMaxIndex))))
    fail(concat("its active voxels reach index ", indexMin_.x, " ", indexMin_.y, " ", indexMin_.z,
                " .. ", indexMax_.x, " ", indexMax_.y, " ", indexMax_.z, "; expected within +-",
                kMaxIndex));
  // Where particles may go: the active voxels' centres.
  bounds_.min = origin_ + glm::vec3(indexMin_) * voxelSize_;
  bounds_.max = origin_ + glm::vec3(indexMax_) * voxelSize_;
  if (!std::isfinite(bounds_.min.x + bounds_.min.y + bounds_.min.z + bounds_.max.x + bounds_.max.y +
                     bounds_.max.z))
    fail("its voxels' positions pass float's range");
}

glm::vec3 SparseField::voxel(const glm::ivec3& ijk) const {
  const pnanovdb_buf_t buf = bufferOf(words_);
  pnanovdb_readaccessor_t acc;
  pnanovdb_readaccessor_init(&acc, rootOf(buf));
  const pnanovdb_coord_t c = {ijk.x, ijk.y, ijk.z};
  return readVec3(buf, pnanovdb_readaccessor_get_value_address(kType, buf, &acc, &c));
}

bool SparseField::active(const glm::ivec3& ijk) const {
  const pnanovdb_buf_t buf = bufferOf(words_);
  pnanovdb_readaccessor_t acc;
  pnanovdb_readaccessor_init(&acc, rootOf(buf));
  const pnanovdb_coord_t c = {ijk.x, ijk.y, ijk.z};
  return pnanovdb_readaccessor_is_active(kType, buf, &acc, &c);
}

// The twin of sparseSample() in shaders/field_sparse.glsl: the same
// operations in the same order (the build has -ffp-contract=off).
glm::vec3 SparseField::sample(const glm::vec3& p) const {
  // Two voxels beyond the active box every corner reads the background, and
  // the index stays far from int's range.
  const glm::vec3 lo = glm::vec3(indexMin_ - 2), hi = glm::vec3(indexMax_ + 1);
  glm::vec3 u = glm::clamp((p - origin_) * indexScale_, lo, hi);
  for (int a = 0; a < 3; ++a)
    if (std::isnan(u[a])) u[a] = lo[a];  // no index for NaN: the background
  const glm::ivec3 i0 = glm::ivec3(glm::floor(u));
  const glm::vec3 f = u - glm::vec3(i0);
  const pnanovdb_buf_t buf = bufferOf(words_);
  pnanovdb_readaccessor_t acc;
  pnanovdb_readaccessor_init(&acc, rootOf(buf));
  glm::vec3 c[8];
  for (int k = 0; k < 8; ++k) {
    const pnanovdb_coord_t at = {i0.x + (k & 1), i0.y + ((k >> 1) & 1), i0.z + ((k >> 2) & 1)};
    c[k] = readVec3(buf, pnanovdb_readaccessor_get_value_address(kType, buf, &acc, &at));
  }
  const glm::vec3 c00 = c[0] + (c[1] - c[0]) * f.x;
  const glm::vec3 c10 = c[2] + (c[3] - c[2]) * f.x;
  const glm::vec3 c01 = c[4] + (c[5] - c[4]) * f.x;
  const glm::vec3 c11 = c[6] + (c[7] - c[6]) * f.x;
  const glm::vec3 c0 = c00 + (c10 - c00) * f.y;
  const glm::vec3 c1 = c01 + (c11 - c01) * f.y;
  return c0 + (c1 - c0) * f.z;
}

void SparseField::forEachActive(
    const std::function<void(const glm::vec3&, std::uint64_t)>& visit) const {
  const pnanovdb_buf_t buf = bufferOf(words_);
  const pnanovdb_grid_handle_t grid = {pnanovdb_address_null()};
  const pnanovdb_tree_handle_t tree = pnanovdb_grid_get_tree(buf, grid);
  const pnanovdb_root_handle_t root = rootOf(buf);
  const std::uint32_t tiles = pnanovdb_root_get_tile_count(buf, root);
  for (std::uint32_t n = 0; n < tiles; ++n) {
    const pnanovdb_root_tile_handle_t tile = pnanovdb_root_get_tile(kType, root, n);
    if (pnanovdb_root_tile_get_child(buf, tile) == 0 && pnanovdb_root_tile_get_state(buf, tile))
      visit(readVec3(buf, pnanovdb_root_tile_get_value_address(kType, buf, tile)),
            std::uint64_t(4096) * 4096 * 4096);
  }
  const std::uint64_t base = PNANOVDB_GRID_SIZE;
  const std::uint64_t uppers = pnanovdb_tree_get_node_count_upper(buf, tree);
  for (std::uint64_t u = 0; u < uppers; ++u) {
    const pnanovdb_upper_handle_t node = {{base + pnanovdb_tree_get_node_offset_upper(buf, tree) +
                                           u * PNANOVDB_GRID_TYPE_GET(kType, upper_size)}};
    for (std::uint32_t n = 0; n < 32768; ++n)
      if (!pnanovdb_upper_get_child_mask(buf, node, n) &&
          pnanovdb_upper_get_value_mask(buf, node, n))
        visit(readVec3(buf, pnanovdb_upper_get_table_address(kType, buf, node, n)),
              128 * 128 * 128);
  }
  const std::uint64_t lowers = pnanovdb_tree_get_node_count_lower(buf, tree);
  for (std::uint64_t l = 0; l < lowers; ++l) {
    const pnanovdb_lower_handle_t node = {{base + pnanovdb_tree_get_node_offset_lower(buf, tree) +
                                           l * PNANOVDB_GRID_TYPE_GET(kType, lower_size)}};
    for (std::uint32_t n = 0; n < 4096; ++n)
      if (!pnanovdb_lower_get_child_mask(buf, node, n) &&
          pnanovdb_lower_get_value_mask(buf, node, n))
        visit(readVec3(buf, pnanovdb_lower_get_table_address(kType, buf, node, n)), 8 * 8 * 8);
  }
  const std::uint64_t leaves = pnanovdb_tree_get_node_count_leaf(buf, tree);
  for (std::uint64_t l = 0; l < leaves; ++l) {
    const pnanovdb_leaf_handle_t node = {{base + pnanovdb_tree_get_node_offset_leaf(buf, tree) +
                                          l * PNANOVDB_GRID_TYPE_GET(kType, leaf_size)}};
    for (std::uint32_t n = 0; n < 512; ++n)
      if (pnanovdb_leaf_get_value_mask(buf, node, n))
        visit(readVec3(buf, pnanovdb_leaf_get_table_address(kType, buf, node, n)), 1);
  }
}

VectorField SparseField::overview(int maxAxis) const {
  const glm::ivec3 voxels = indexMax_ - indexMin_ + 1;
  const glm::ivec3 dims = glm::clamp(voxels, glm::ivec3(1), glm::ivec3(std::max(maxAxis, 1)));
  VectorField out(bounds_, dims);
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i)
        out.at(i, j, k) = sample(out.pointPosition(i, j, k));
  return out;
}

}  // namespace sandstorm
