// SparseField: a sparse grid of vectors, kept as NanoVDB keeps it (a tree of
// 8^3 leaves under 16^3 and 32^3 nodes, one buffer of 32-bit words), so a grid
// whose bounding box would be 4096^3 costs the memory of its active voxels only.
// The GPU gets the very words (contexts/particles/gpu_sparse_field.h) and reads
// them with NanoVDB's PNanoVDB.h in GLSL; this class reads them with the same
// header in C, and sample() performs the operations of
// shaders/field_sparse.glsl in the same order, so the CPU twin and the GPU agree.
//
// Layout: voxel (i, j, k) sits at origin + (i, j, k) * voxelSize (an
// axis-aligned grid: NanoVDB's map is a scale and a translation). Sampling is
// trilinear between voxel centres; a voxel that is not active reads the
// grid's background value (OpenVDB's BoxSampler does the same). bounds() is the
// box of the active voxels' centres: where particles may go.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/field/box.h"
#include "core/field/vector_field.h"

namespace sandstorm {

class SparseField {
 public:
  // The words of a NanoVDB buffer whose first grid is a Vec3f grid with an
  // axis-aligned transform (positive scale, no rotation or shear). Throws
  // Error naming `source` when the buffer is too short for what its header
  // claims, is not NanoVDB, holds another value type, or is rotated.
  SparseField(std::vector<std::uint32_t> words, const std::string& source);

  glm::vec3 sample(const glm::vec3& p) const;
  // The value at voxel ijk (the background where no voxel is active).
  glm::vec3 voxel(const glm::ivec3& ijk) const;
  bool active(const glm::ivec3& ijk) const;

  const Box& bounds() const { return bounds_; }
  const glm::vec3& origin() const { return origin_; }
  const glm::vec3& voxelSize() const { return voxelSize_; }
  // 1 / voxelSize per axis: multiplies (p - origin) into index space. The GPU
  // gets this very value, so both sides compute the same indices.
  const glm::vec3& indexScale() const { return indexScale_; }
  const glm::ivec3& indexMin() const { return indexMin_; }
  const glm::ivec3& indexMax() const { return indexMax_; }
  std::uint64_t activeVoxelCount() const { return activeVoxels_; }

  std::span<const std::uint32_t> words() const { return words_; }
  std::size_t byteSize() const { return words_.size() * 4; }

  // Every active value: each active voxel once (count 1), each active tile
  // once with the voxels it stands for.
  void forEachActive(
      const std::function<void(const glm::vec3& value, std::uint64_t count)>& visit) const;

  // The field sampled onto a dense grid over bounds() with at most `maxAxis`
  // points along an axis (fewer where the active box has fewer voxels): what
  // needs a dense grid (bounds, previews, the field tool) without the full one.
  VectorField overview(int maxAxis) const;

 private:
  std::vector<std::uint32_t> words_;
  Box bounds_;
  glm::vec3 origin_{0.0f}, voxelSize_{1.0f}, indexScale_{1.0f};
  glm::ivec3 indexMin_{0}, indexMax_{0};
  std::uint64_t activeVoxels_ = 0;
};

}  // namespace sandstorm
