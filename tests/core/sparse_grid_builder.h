// Test helper: a NanoVDB Vec3f grid built with NanoVDB's own GridBuilder (an
// independent writer of the layout SparseField reads), as SparseField's words.
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

#include <nanovdb/util/GridBuilder.h>
#include <glm/glm.hpp>

namespace sandstorm::test {

// `fill(set)` calls set(ijk, value) for each active voxel.
inline std::vector<std::uint32_t> buildSparseGrid(
    const std::function<void(const std::function<void(glm::ivec3, glm::vec3)>&)>& fill,
    double voxelSize = 1.0, glm::dvec3 origin = glm::dvec3(0.0),
    glm::vec3 background = glm::vec3(0.0f)) {
  nanovdb::GridBuilder<nanovdb::Vec3f> builder(
      nanovdb::Vec3f(background.x, background.y, background.z));
  auto acc = builder.getAccessor();
  fill([&](glm::ivec3 ijk, glm::vec3 v) {
    acc.setValue(nanovdb::Coord(ijk.x, ijk.y, ijk.z), nanovdb::Vec3f(v.x, v.y, v.z));
  });
  auto handle = builder.getHandle<>(voxelSize, nanovdb::Vec3d(origin.x, origin.y, origin.z), "v");
  std::vector<std::uint32_t> words((handle.size() + 3) / 4, 0u);
  std::memcpy(words.data(), handle.data(), handle.size());
  return words;
}

}  // namespace sandstorm::test
