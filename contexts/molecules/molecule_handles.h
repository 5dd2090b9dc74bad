// MoleculeHandles: a frame's molecules as another wall on the same GPU can
// draw and read them (SimulationShare publishes the owner's): the members'
// buffers, the control block with the live count and the instanced draw
// command (every molecule's vertices in one draw), and the molecule block
// describing their shape. Plain GL names.
#pragma once

#include <cstddef>
#include <cstdint>

namespace sandstorm {

struct MoleculeHandles {
  std::uint32_t positionLife = 0, velocityKind = 0, control = 0, block = 0;
  std::uint32_t countOffset = 0, drawOffset = 0;
  int members = 0;
  std::uint32_t stride = 0;   // member j of molecule i is record j * stride + i
  std::size_t lateCount = 0;  // live molecules a frame or two ago
  explicit operator bool() const { return positionLife != 0 && block != 0 && members > 0; }
};

}  // namespace sandstorm
