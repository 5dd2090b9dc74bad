// A sparse grid (FIELD_SPARSE programs): the NanoVDB words of
// core/field/sparse_field.h, read with NanoVDB's PNanoVDB.h. sparseSample() is
// the twin of SparseField::sample(): the same corners, the same arithmetic in
// the same order. Needs sim_block.glsl: fieldMin holds the grid's origin,
// fieldIndexScale 1 / voxel size, sparseIndexMin/Max the active voxels' index
// box widened to where every corner reads the background.
//
// The words lie in two storage buffers (GpuSparseField): those below
// kSparseSplitWords at binding 14, the rest at 15 (the same buffer when the
// grid is smaller), so a grid may pass one buffer's limit (2 GiB on NVIDIA)
// up to NanoVDB's 32-bit addressing's 4 GiB. FIELD_SPARSE_ONE_BUFFER (the
// particle update, for a grid below the split): every word is in the first.

#ifdef FIELD_SPARSE
const uint kSparseSplitWords = 0x1FFC0000u;  // 2 GiB less 1 MiB: contexts/particles/gpu_sparse_field.cpp
layout(std430, binding = 14) readonly restrict buffer SparseLow { uint sparseLow[]; };
layout(std430, binding = 15) readonly restrict buffer SparseHigh { uint sparseHigh[]; };

// PNanoVDB's buffer, ours (PNANOVDB_BUF_CUSTOM): what its GLSL one declares.
#define PNANOVDB_GLSL
#define PNANOVDB_BUF_CUSTOM
struct pnanovdb_buf_t {
  uint unused;
};
uint pnanovdb_buf_read_uint32(pnanovdb_buf_t buf, uint byte_offset) {
  uint w = byte_offset >> 2u;
#ifdef FIELD_SPARSE_ONE_BUFFER
  return sparseLow[w];
#else
  return w < kSparseSplitWords ? sparseLow[w] : sparseHigh[w - kSparseSplitWords];
#endif
}
uvec2 pnanovdb_buf_read_uint64(pnanovdb_buf_t buf, uint byte_offset) {
  return uvec2(pnanovdb_buf_read_uint32(buf, byte_offset),
               pnanovdb_buf_read_uint32(buf, byte_offset + 4u));
}
#define pnanovdb_grid_type_t uint
#define PNANOVDB_GRID_TYPE_GET(grid_typeIn, nameIn) pnanovdb_grid_type_constants[grid_typeIn].nameIn
#include "PNanoVDB.h"

// A voxel's three floats: the buffer chosen once for the three words, not
// for each (the split may fall inside a value: then word by word).
vec3 sparseValue(pnanovdb_buf_t buf, pnanovdb_address_t a) {
  uint w = a.byte_offset >> 2u;
#ifndef FIELD_SPARSE_ONE_BUFFER
  if (w + 2u >= kSparseSplitWords) {
    if (w < kSparseSplitWords)
      return vec3(pnanovdb_read_float(buf, a), pnanovdb_read_float(buf, pnanovdb_address_offset(a, 4u)),
                  pnanovdb_read_float(buf, pnanovdb_address_offset(a, 8u)));
    w -= kSparseSplitWords;
    return uintBitsToFloat(uvec3(sparseHigh[w], sparseHigh[w + 1u], sparseHigh[w + 2u]));
  }
#endif
  return uintBitsToFloat(uvec3(sparseLow[w], sparseLow[w + 1u], sparseLow[w + 2u]));
}

vec3 sparseSample(vec3 p) {
  precise vec3 u = clamp((p - sim.fieldMin.xyz) * sim.fieldIndexScale.xyz, sim.sparseIndexMin.xyz,
                         sim.sparseIndexMax.xyz);
  ivec3 i0 = ivec3(floor(u));
  precise vec3 f = u - vec3(i0);
  pnanovdb_buf_t buf;
  buf.unused = 0u;
  pnanovdb_grid_handle_t grid;
  grid.address.byte_offset = 0u;
  pnanovdb_readaccessor_t acc;
  pnanovdb_readaccessor_init(acc, pnanovdb_tree_get_root(buf, pnanovdb_grid_get_tree(buf, grid)));
  // A cell within one leaf (two cells in three): its corners' values lie at
  // fixed strides from the first's (voxel n = 64 x + 8 y + z, 12 bytes each),
  // so only the first walks the tree. One walk in the loop's body keeps the
  // program small.
  pnanovdb_address_t first;
  bool oneLeaf = false;
  vec3 c[8];
  for (int k = 0; k < 8; ++k) {
    pnanovdb_address_t a;
    if (oneLeaf) {
      a = pnanovdb_address_offset(first,
                                  uint(768 * (k & 1) + 96 * ((k >> 1) & 1) + 12 * (k >> 2)));
    } else {
      uint level = 0u;
      a = pnanovdb_readaccessor_get_value_address_and_level(
          PNANOVDB_GRID_TYPE_VEC3F, buf, acc, i0 + ivec3(k & 1, (k >> 1) & 1, k >> 2), level);
      if (k == 0) {
        first = a;
        oneLeaf = level == 0u && all(lessThan(i0 & 7, ivec3(7)));
      }
    }
    c[k] = sparseValue(buf, a);
  }
  return trilinear(f, c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]);
}
#endif  // FIELD_SPARSE
