#include "core/molecules/molecule_grid.h"

#include <cmath>

namespace sandstorm {

glm::ivec3 MoleculeGrid::cellOf(const glm::vec3& p, float invRadius) {
  return glm::ivec3(int(std::floor(p.x * invRadius)), int(std::floor(p.y * invRadius)),
                    int(std::floor(p.z * invRadius)));
}

MoleculeGrid::MoleculeGrid(std::span<const glm::vec3> centres, float radius)
    : centres_(centres), radius_(radius), invRadius_(1.0f / radius) {
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const glm::ivec3 c = cellOf(centres[i], invRadius_);
    cells_[{c.x, c.y, c.z}].push_back(std::uint32_t(i));
  }
}

glm::vec3 MoleculeGrid::displacement(std::size_t i, float share) const {
  const glm::vec3 me = centres_[i];
  const glm::ivec3 cell = cellOf(me, invRadius_);
  glm::vec3 sum(0.0f);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const auto it = cells_.find({cell.x + dx, cell.y + dy, cell.z + dz});
        if (it == cells_.end()) continue;
        for (const std::uint32_t j : it->second) {
          if (j == i) continue;
          const glm::vec3 d = me - centres_[j];
          const float r = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
          if (!(r > 0.0f && r < radius_)) continue;
          sum = sum + d * (share * (radius_ - r) / r);
        }
      }
  return sum;
}

}  // namespace sandstorm
