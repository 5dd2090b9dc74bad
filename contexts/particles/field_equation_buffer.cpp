#include "contexts/particles/field_equation_buffer.h"

#include <epoxy/gl.h>

#include "contexts/particles/equation_block.h"

namespace sandstorm {

void FieldEquationBuffer::set(std::shared_ptr<const FieldEquation> equation) {
  equation_ = std::move(equation);
  if (!equation_) return;
  if (!block_) {
    block_ = gl::createBuffer();
    glNamedBufferStorage(block_.id(), sizeof(EquationBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  const EquationBlock b = makeEquationBlock(*equation_);
  glNamedBufferSubData(block_.id(), 0, sizeof(b), &b);
}

bool FieldEquationBuffer::bindIfUsed(const ParticleState& state) const {
  if (!equation_ || state.field.mode != FieldMode::Equation) return false;
  glBindBufferBase(GL_UNIFORM_BUFFER, 3, block_.id());
  return true;
}

}  // namespace sandstorm
