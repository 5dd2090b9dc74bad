#include "core/sim/physics_world.h"

#include "core/obstacles/collision_shapes.h"

namespace sandstorm {

void PhysicsWorld::setField(std::shared_ptr<const VectorField> field,
                            const FieldPlacement& placement,
                            std::shared_ptr<const VectorField> next) {
  field_ = std::move(field);
  next_ = std::move(next);
  placement_ = placement;
}

PhysicsInputs PhysicsWorld::inputs(const SimStep& step, const ParticleState& state) {
  PhysicsInputs in;
  in.field = field_.get();
  in.nextField = next_.get();
  in.sparse = field_ ? sparse_.get() : nullptr;
  in.blend = step.fieldBlend;
  in.pointwiseBlend = pointwiseBlend_;
  in.placement = placement_;
  in.terrain = terrain_.get();
  in.settings = state.sim;
  in.dt = step.dt;
  in.obstacles = collisionShapes(state, terrain_.get());
  if (state.field.mode == FieldMode::Expression) {
    if (!expression_ || expression_->text() != state.field.expression)
      expression_ = FieldExpression::compile(state.field.expression);
    in.expression = expression_.get();
    in.time = float(step.time);
  }
  return in;
}

}  // namespace sandstorm
