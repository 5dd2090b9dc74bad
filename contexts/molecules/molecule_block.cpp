#include "contexts/molecules/molecule_block.h"

namespace sandstorm {

int moleculeVertices(const MoleculeShape& shape) {
  return shape.faces.empty() ? 6 * int(shape.lines.size()) : 3 * int(shape.faces.size());
}

MoleculeBlock makeMoleculeBlock(const MoleculeSettings& s, float dt, std::size_t capacity,
                                std::uint32_t tableMask) {
  const MoleculeParams p = moleculeParams(s, dt);
  const MoleculeShape& shape = moleculeShape(s.complexity);
  MoleculeBlock b{};
  b.shape = glm::ivec4(p.members, p.iterations, int(shape.springs.size()), p.solid ? 1 : 0);
  b.mass = glm::vec4(p.headMass, p.invHeadMass, p.invTotalMass, p.passStiffness);
  b.motion = glm::vec4(p.damping, p.invDt, s.size, p.invMembers);
  b.push = glm::vec4(p.push.pushCentre, p.push.pushRadius);
  b.pushMore = glm::vec4(p.push.pushSpeed, p.push.push ? 1.0f : 0.0f, p.invTailMembers, 0.0f);
  b.repulsion = glm::vec4(p.repulsion ? 1.0f : 0.0f, p.repulsionRadius, 1.0f / p.repulsionRadius,
                          p.repulsionShare);
  b.grid = glm::uvec4(tableMask, std::uint32_t(capacity), 0, 0);
  for (std::size_t k = 0; k < shape.springs.size(); ++k)
    b.springs[k] = glm::vec4(float(shape.springs[k].a), float(shape.springs[k].b),
                             p.springLength[k], p.springFactor[k]);
  for (int j = 0; j < shape.members; ++j)
    b.rest[j] = glm::vec4(shape.rest[std::size_t(j)], p.vaneReach[std::size_t(j)]);
  for (std::size_t f = 0; f < shape.faces.size(); ++f)
    b.faces[f] = glm::ivec4(shape.faces[f][0], shape.faces[f][1], shape.faces[f][2], 0);
  for (std::size_t l = 0; l < shape.lines.size(); ++l)
    b.lines[l] = glm::ivec4(shape.lines[l][0], shape.lines[l][1], 0, 0);
  b.drawing =
      glm::ivec4(int(shape.faces.size()), int(shape.lines.size()), moleculeVertices(shape), 0);
  b.look = glm::vec4(s.width, 0.0f, 0.0f, 0.0f);
  return b;
}

}  // namespace sandstorm
