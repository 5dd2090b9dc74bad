#include "contexts/particles/sim_block.h"

#include "core/obstacles/obstacle_physics.h"
#include "core/sim/particle_physics.h"

namespace sandstorm {

int fillSimBlock(const SimBlockInputs& in, SimBlock& b) {
  b = SimBlock{};
  const SimSettings& s = in.state->sim;
  if (in.field) {
    b.fieldMin = glm::vec4(in.field->bounds().min, 0.0f);
    b.fieldIndexScale = glm::vec4(in.field->indexScale(), 0.0f);
    b.fieldDims = glm::ivec4(in.field->dims(), 1);
    const Box domain = particleDomain(*in.field);
    b.domainMin = glm::vec4(domain.min, 0.0f);
    b.domainMax = glm::vec4(domain.max, 0.0f);
  }
  if (in.field && in.sparse) {
    // The same numbers as SparseField::sample() uses.
    b.fieldMin = glm::vec4(in.sparse->origin(), 0.0f);
    b.fieldIndexScale = glm::vec4(in.sparse->indexScale(), 0.0f);
    b.sparseIndexMin = glm::vec4(glm::vec3(in.sparse->indexMin() - 2), 0.0f);
    b.sparseIndexMax = glm::vec4(glm::vec3(in.sparse->indexMax() + 1), 0.0f);
  }
  const bool masked = (in.field && in.field->hasValidity()) ||
                      (in.nextField && in.nextField->hasValidity()) ||
                      (in.blendedNext && in.blendedNext->hasValidity());
  b.fieldBlend =
      glm::vec4(in.step.fieldBlend, in.nextField ? 1.0f : 0.0f, masked ? 1.0f : 0.0f, 0.0f);
  b.placementOffset = glm::vec4(in.placement.offset, in.placement.scale);
  for (int c = 0; c < 3; ++c)
    b.placementRotation[c] = glm::vec4(in.placement.rotation[c], 0.0f);
  b.gravity = glm::vec4(s.gravity, 1.0f / s.dragTime);
  b.stepParams = glm::vec4(in.step.dt, s.fieldStrength, s.restitution, 1.0f / in.placement.scale);
  b.modes =
      glm::ivec4(int(s.motion), int(s.integrator), int(s.boundary), s.groundCollision ? 1 : 0);
  const int emitterCount = int(in.state->emitters.size());
  b.frameSeed =
      glm::uvec4(in.step.frame, in.step.seed.lo, in.step.seed.hi, std::uint32_t(emitterCount));
  if (in.terrain) {
    b.terrainMinScale = glm::vec4(in.terrain->min(), in.terrain->indexScale());
    b.terrainDims = glm::ivec4(in.terrain->dims(), 1, 0);
  }
  const std::vector<Obstacle> obstacles =
      collisionShapes(*in.state, in.terrain ? in.terrain : in.obstacleGround);
  b.expression = glm::vec4(float(in.step.time), 0.0f, 0.0f, 0.0f);
  b.obstacleCount = glm::ivec4(int(obstacles.size()), 0, 0, 0);
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const Obstacle& o = obstacles[i];
    ObstacleBlock& ob = b.obstacles[i];
    ob.positionRadius = glm::vec4(o.position, o.radius);
    // A sphere's x: its potential-flow strength R^3 / 2; a box's: half its size.
    ob.halfSize = o.shape == ObstacleShape::Sphere
                      ? glm::vec4(sphereStrength(o), 0.0f, 0.0f, 0.5f * o.height)
                      : glm::vec4(0.5f * o.size, 0.5f * o.height);
    ob.velocity = glm::vec4(o.velocity, o.restitution);
    ob.shapeFlow = glm::ivec4(int(o.shape), o.flow ? 1 : 0, 0, 0);
  }
  int slots = 0;
  for (int e = 0; e < emitterCount; ++e) {
    const Emitter& em = in.state->emitters[std::size_t(e)];
    const int granted = e < int(in.granted.size()) ? int(in.granted[std::size_t(e)]) : 0;
    EmitterBlock& eb = b.emitters[e];
    eb.position = glm::vec4(em.position, 0.0f);
    eb.size = glm::vec4(em.width, em.depth, em.height, em.radius);
    eb.life = glm::vec4(em.lifetime, em.lifetimeVariance, em.spread, 0.0f);
    eb.velocity = glm::vec4(em.velocity, 0.0f);
    eb.shapeCount = glm::ivec4(int(em.shape), granted, slots, 0);
    slots += (granted + kEmissionSlotSize - 1) / kEmissionSlotSize;
  }
  return slots;
}

}  // namespace sandstorm
