// SimBlock: the std140 uniform block of shaders/sim_block.glsl, filled from the
// state, the field and the step. The two declarations must stay in step; the
// static_asserts and the GPU/CPU agreement tests guard them.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/field/field_placement.h"
#include "core/field/height_map.h"
#include "core/field/sparse_field.h"
#include "core/field/vector_field.h"
#include "core/obstacles/collision_shapes.h"
#include "core/sim/particle_state.h"
#include "core/sim/sim_step.h"

namespace sandstorm {

struct alignas(16) EmitterBlock {
  glm::vec4 position;
  glm::vec4 size;  // width, depth, height, radius
  glm::vec4 life;  // lifetime, lifetime variance, spread
  glm::vec4 velocity;
  glm::ivec4 shapeCount;  // shape, granted count, first slot
};

struct alignas(16) ObstacleBlock {
  glm::vec4 positionRadius;
  glm::vec4 halfSize;  // a box's half extent (a sphere's x: R^3 / 2); w: a cylinder's half height
  glm::vec4 velocity;  // w: restitution
  glm::ivec4 shapeFlow;
};

struct alignas(16) SimBlock {
  glm::vec4 fieldMin;
  glm::vec4 fieldIndexScale;
  glm::ivec4 fieldDims;
  glm::vec4 domainMin;
  glm::vec4 domainMax;
  glm::vec4 placementOffset;
  glm::vec4 placementRotation[3];
  glm::vec4 gravity;
  glm::vec4 stepParams;
  glm::ivec4 modes;
  glm::uvec4 frameSeed;
  glm::vec4 terrainMinScale;
  glm::ivec4 terrainDims;
  glm::vec4 fieldBlend;  // x: weight towards the next frame, y: 1 when there is one,
                         // z: 1 when a frame has a validity mask
  EmitterBlock emitters[ParticleState::kMaxEmitters];
  glm::vec4 expression;      // x: simulated seconds before this step
  glm::ivec4 obstacleCount;  // x: how many of obstacles[] are in use
  ObstacleBlock obstacles[kMaxCollisionShapes];
  // A sparse grid's index box widened to where every corner reads the
  // background (FIELD_SPARSE programs; SparseField::sample).
  glm::vec4 sparseIndexMin;
  glm::vec4 sparseIndexMax;
};

static_assert(sizeof(EmitterBlock) == 80);
static_assert(sizeof(ObstacleBlock) == 64);
static_assert(sizeof(SimBlock) ==
              16 * 16 + 80 * ParticleState::kMaxEmitters + 32 + 64 * kMaxCollisionShapes + 32);

// Newborn particles per emission slot (one geometry-shader invocation).
inline constexpr int kEmissionSlotSize = 64;

struct SimBlockInputs {
  const VectorField* field = nullptr;
  const VectorField* nextField = nullptr;
  // A next frame already blended into the grid the program reads
  // (FieldPairBlend): no blend in the shader, but its validity mask counts.
  const VectorField* blendedNext = nullptr;
  // A sparse grid read in place of `field` (whose bounds are its bounds).
  const SparseField* sparse = nullptr;
  FieldPlacement placement;
  const HeightMap* terrain = nullptr;
  // The ground the helicopter's height is measured from, when `terrain` (what
  // particles collide with) is not given: the scene's streaklines fly over it.
  const HeightMap* obstacleGround = nullptr;
  const ParticleState* state = nullptr;
  SimStep step;
  std::vector<std::uint32_t> granted;  // newborn per emitter, after the budget
};

// Fills the block; returns the number of emission slots to draw.
int fillSimBlock(const SimBlockInputs& in, SimBlock& block);

}  // namespace sandstorm
