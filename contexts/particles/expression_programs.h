// ExpressionPrograms: the particle update's programs for field.mode =
// expression (core/expr/field_expression.h), one per expression and variant,
// compiled with its GLSL (FIELD_EXPRESSION, EXPRESSION_X/_Y/_Z) when the
// expression is first used. A program the driver refuses is reported once in
// the log and the last good one of that variant is kept, so a run never stops
// for an expression. Needs the GL context current.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "contexts/gl/program.h"
#include "core/sim/particle_state.h"

namespace sandstorm {

class ExpressionPrograms {
 public:
  // Builds a program of the variant from its defines.
  using Make = std::function<gl::Program(const std::vector<std::string>& defines)>;

  // The program for the state's expression and the variant's `defines`; null
  // when none ever compiled for this variant.
  const gl::Program* get(const ParticleState& state, const std::vector<std::string>& defines,
                         const Make& make);

 private:
  std::map<std::string, std::unique_ptr<gl::Program>> programs_;  // by variant + expression
  std::map<std::string, const gl::Program*> lastGood_;            // by variant
  std::set<std::string> failed_;
};

}  // namespace sandstorm
