// expressionToGlsl: one component of a field written at run time (muParser's
// language: field_expression.h) as a GLSL float expression, for the particle
// update's FIELD_EXPRESSION programs (shaders/field_expression.glsl).
//
// The language is muParser's, precedence and all: ?: (lowest, right to
// left), ||, &&, the comparisons == != < > <= >=, + -, * /, unary - and +,
// ^ (highest, right to left: -2^2 = -4, 2^3^2 = 512); numbers; the
// variables x y z t vx vy vz age; the constants _pi and _e; the functions
// sin cos tan asin acos atan sinh cosh tanh asinh acosh atanh exp ln log
// (natural) log2 log10 sqrt abs sign rint atan2 min max sum avg. Comparisons
// and logic give 1 or 0 as muParser does; ^ of a negative base is defined for
// whole exponents (GLSL's pow is not). Anything else is refused with the
// position, counted from 0 as muParser counts.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace sandstorm {

struct ExpressionError : std::runtime_error {
  ExpressionError(std::size_t position, const std::string& message)
      : std::runtime_error(message), position(position) {}
  std::size_t position;  // where in the text, from 0
};

// GLSL for the expression; the variables are e_x, e_y, e_z, e_t, e_vx, e_vy,
// e_vz, e_age. Throws ExpressionError.
std::string expressionToGlsl(std::string_view source);

}  // namespace sandstorm
