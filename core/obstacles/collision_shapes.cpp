#include "core/obstacles/collision_shapes.h"

#include "core/obstacles/helicopter_shape.h"

namespace sandstorm {

static_assert(ParticleState::kMaxObstacles + 5 <= kMaxCollisionShapes,
              "the obstacles and the helicopter's five solid parts");

std::vector<Obstacle> collisionShapes(const ParticleState& state, const HeightMap* terrain) {
  std::vector<Obstacle> out;
  for (const Obstacle& o : state.obstacles)
    if (o.enabled) out.push_back(o);
  for (const Obstacle& o :
       helicopterObstacles(state.helicopter, HelicopterModel{}.rotorRadius, terrain))
    out.push_back(o);
  return out;
}

}  // namespace sandstorm
