// MoleculeGrid: the molecules' repulsion (MoleculeSettings::repulsion), the
// CPU twin of the GPU's grid (contexts/molecules/molecule_grid_gpu.h).
// Molecule centres go into cubic cells as wide as the repulsion radius;
// molecule i is pushed away from every other centre closer than the radius,
// by `share` of the overlap, summed over the 27 cells around its own (z, then
// y, then x, from -1 to 1) and, within a cell, in the molecules' order. That
// order is what the GPU's stable sort by cell gives, so both add the same
// terms in the same order.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <tuple>
#include <vector>

#include <glm/glm.hpp>

namespace sandstorm {

class MoleculeGrid {
 public:
  MoleculeGrid(std::span<const glm::vec3> centres, float radius);

  // Molecule i's displacement this step.
  glm::vec3 displacement(std::size_t i, float share) const;

  // The cell of a point: floor(p * (1 / radius)), as the shader computes it.
  static glm::ivec3 cellOf(const glm::vec3& p, float invRadius);

 private:
  std::span<const glm::vec3> centres_;
  float radius_, invRadius_;
  std::map<std::tuple<int, int, int>, std::vector<std::uint32_t>> cells_;
};

}  // namespace sandstorm
