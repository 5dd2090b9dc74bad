// MoleculeBlock: the std140 uniform block of shaders/molecule_block.glsl
// (binding 5), filled from the molecules' settings through MoleculeParams,
// so the GPU steps with the very floats the CPU reference uses.
#pragma once

#include <glm/glm.hpp>

#include "core/molecules/molecule_physics.h"
#include "core/molecules/molecule_shape.h"

namespace sandstorm {

struct alignas(16) MoleculeBlock {
  glm::ivec4 shape;
  glm::vec4 mass;
  glm::vec4 motion;
  glm::vec4 push;
  glm::vec4 pushMore;
  glm::vec4 repulsion;
  glm::uvec4 grid;
  glm::vec4 springs[MoleculeShape::kMaxSprings];
  glm::vec4 rest[MoleculeSettings::kMaxComplexity];
  glm::ivec4 faces[MoleculeShape::kMaxFaces];
  glm::ivec4 lines[MoleculeSettings::kMaxComplexity];
  glm::ivec4 drawing;
  glm::vec4 look;
};

static_assert(sizeof(MoleculeBlock) == 16 * (7 + 16 + 8 + 4 + 8 + 2));

// Vertices a molecule of the shape draws: three a face, six a ribbon.
int moleculeVertices(const MoleculeShape& shape);

// `capacity`: the molecules the buffers hold (member j of molecule i is
// record j * capacity + i); `tableMask`: the repulsion table's size - 1
// (MoleculeGridGpu).
MoleculeBlock makeMoleculeBlock(const MoleculeSettings& settings, float dt, std::size_t capacity,
                                std::uint32_t tableMask = 0);

}  // namespace sandstorm
