// EquationBlock: the std140 uniform block of shaders/field_equation.glsl
// (binding 3), filled from a FieldEquation.
#pragma once

#include <glm/glm.hpp>

#include "core/field/field_equation.h"

namespace sandstorm {

struct alignas(16) EquationTermBlock {
  glm::ivec4 kindSeed;
  glm::vec4 a, b, c;
};

struct alignas(16) EquationBlock {
  glm::ivec4 termCount;
  EquationTermBlock terms[FieldEquation::kMaxTerms];
};

static_assert(sizeof(EquationTermBlock) == 64);
static_assert(sizeof(EquationBlock) == 16 + 64 * FieldEquation::kMaxTerms);

EquationBlock makeEquationBlock(const FieldEquation& equation);

}  // namespace sandstorm
