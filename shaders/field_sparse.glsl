// A sparse grid (FIELD_SPARSE programs): the NanoVDB words of
// core/field/sparse_field.h in the storage buffer the dense grid's programs
// read as FieldGrid (binding 14), read with NanoVDB's PNanoVDB.h. sparseSample()
// is the twin of SparseField::sample(): the same operations in the same order.
// Needs sim_block.glsl: fieldMin holds the grid's origin, fieldIndexScale
// 1 / voxel size, sparseIndexMin/Max the active voxels' index box widened to
// where every corner reads the background.

#ifdef FIELD_SPARSE
layout(std430, binding = 14) readonly restrict buffer SparseGrid { uint pnanovdb_buf_data[]; };
#define PNANOVDB_GLSL
#include "PNanoVDB.h"

vec3 sparseVoxel(inout pnanovdb_readaccessor_t acc, ivec3 ijk) {
  pnanovdb_buf_t buf;
  buf.unused = 0u;
  pnanovdb_address_t a =
      pnanovdb_readaccessor_get_value_address(PNANOVDB_GRID_TYPE_VEC3F, buf, acc, ijk);
  return vec3(pnanovdb_read_float(buf, a), pnanovdb_read_float(buf, pnanovdb_address_offset(a, 4u)),
              pnanovdb_read_float(buf, pnanovdb_address_offset(a, 8u)));
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
  // A loop, not eight calls: each call inlines NanoVDB's tree walk.
  vec3 c[8];
  for (int k = 0; k < 8; ++k) c[k] = sparseVoxel(acc, i0 + ivec3(k & 1, (k >> 1) & 1, k >> 2));
  return trilinear(f, c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]);
}
#endif  // FIELD_SPARSE
