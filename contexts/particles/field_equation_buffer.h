// FieldEquationBuffer: an analytic field's equation on the GPU (the uniform
// block of shaders/field_equation.glsl, binding 3) for the particle updates'
// FIELD_EQUATION programs. Needs the GL context current.
#pragma once

#include <memory>

#include "contexts/gl/objects.h"
#include "core/field/field_equation.h"
#include "core/sim/particle_state.h"

namespace sandstorm {

class FieldEquationBuffer {
 public:
  void set(std::shared_ptr<const FieldEquation> equation);
  const std::shared_ptr<const FieldEquation>& equation() const { return equation_; }
  // Whether this update evaluates the equation (field.mode = equation and there
  // is one); if so, binds the block.
  bool bindIfUsed(const ParticleState& state) const;

 private:
  std::shared_ptr<const FieldEquation> equation_;
  gl::Buffer block_;
};

}  // namespace sandstorm
