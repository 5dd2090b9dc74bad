// PhysicsWorld: what the CPU twins move particles through (the field, a
// time-varying field's next frame, its placement, the terrain, a field
// expression compiled once per text), turned into each step's PhysicsInputs.
// ReferenceSimulator and MoleculeReference hold one each.
#pragma once

#include <memory>

#include "core/expr/field_expression.h"
#include "core/field/field_placement.h"
#include "core/field/height_map.h"
#include "core/field/vector_field.h"
#include "core/sim/particle_physics.h"
#include "core/sim/particle_state.h"
#include "core/sim/sim_step.h"

namespace sandstorm {

class PhysicsWorld {
 public:
  void setField(std::shared_ptr<const VectorField> field, const FieldPlacement& placement = {},
                std::shared_ptr<const VectorField> next = nullptr);
  // A sparse grid sampled in place of the field (FieldUpdate::sparse); null: none.
  void setSparse(std::shared_ptr<const SparseField> sparse) { sparse_ = std::move(sparse); }
  void setTerrain(std::shared_ptr<const HeightMap> terrain) { terrain_ = std::move(terrain); }
  // How a time-varying field's pair is blended (PhysicsInputs::pointwiseBlend).
  void setPointwiseBlend(bool pointwise) { pointwiseBlend_ = pointwise; }

  // The inputs of one step; valid while this world and its field live.
  PhysicsInputs inputs(const SimStep& step, const ParticleState& state);

 private:
  std::shared_ptr<const VectorField> field_, next_;
  std::shared_ptr<const SparseField> sparse_;
  FieldPlacement placement_;
  std::shared_ptr<const HeightMap> terrain_;
  std::shared_ptr<const FieldExpression> expression_;  // field.mode = expression's, compiled
  bool pointwiseBlend_ = false;
};

}  // namespace sandstorm
