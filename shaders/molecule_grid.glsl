// The molecules' repulsion grid (MoleculeGridGpu): the input molecules'
// centres, their cell keys and indices sorted by key (stably: a key's
// molecules in index order), and where each key's run starts. Needs
// molecule_block.glsl.
layout(std430, binding = 7) restrict buffer GridCentres { vec4 gridCentres[]; };
layout(std430, binding = 8) restrict buffer GridKeys { uint gridKeys[]; };
layout(std430, binding = 9) restrict buffer GridValues { uint gridValues[]; };
layout(std430, binding = 10) restrict buffer GridStarts { uint gridStarts[]; };

const uint kNoStart = 0xffffffffu;

ivec3 gridCell(vec3 p) {
  precise vec3 u = p * molecule.repulsion.z;
  return ivec3(floor(u));
}

uint gridKey(ivec3 c) {
  uvec3 u = uvec3(c);
  return ((u.x * 73856093u) ^ (u.y * 19349663u) ^ (u.z * 83492791u)) & molecule.grid.x;
}

#ifdef GRID_READ
// Molecule i's displacement (MoleculeGrid::displacement): over the 27 cells
// around its own, z then y then x, and within a cell in index order (the
// run of the cell's key, others sharing the key skipped).
vec3 gridDisplacement(uint i) {
  vec3 me = gridCentres[i].xyz;
  ivec3 cell = gridCell(me);
  float radius = molecule.repulsion.y, share = molecule.repulsion.w;
  uint count = ctl.count[uIn];
  precise vec3 sum = vec3(0.0);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        ivec3 c = cell + ivec3(dx, dy, dz);
        uint key = gridKey(c);
        uint start = gridStarts[key];
        if (start == kNoStart) continue;
        for (uint t = start; t < count && gridKeys[t] == key; ++t) {
          uint j = gridValues[t];
          if (j == i) continue;
          vec3 other = gridCentres[j].xyz;
          if (gridCell(other) != c) continue;
          precise vec3 d = me - other;
          precise float r = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
          if (!(r > 0.0 && r < radius)) continue;
          sum = sum + d * (share * (radius - r) / r);
        }
      }
  return sum;
}
#endif
