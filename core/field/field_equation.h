// FieldEquation: an analytic field as numbers a shader can evaluate
// (shaders/field_equation.glsl), instead of the grid it is baked into: the
// texture-vs-equation comparison of the thesis, and fields free of grid error.
//
// A field is a sum of up to kMaxTerms terms; each term is one of the analytic
// fields of core/field with its parameters packed into three vec4 and a seed:
//   tornado   a = (center, range)   b = (unit axis, height)  c = (core, spin, pull, up)
//   gravity   a = (center, range)   b.x = power
//   wind      a = (unit direction, power)  b = (noise, noise scale)  seed: the noise's
//   curl      a = (offset, scale)   b.x = amplitude                  seed: the noise's
//   sphere    a = (center, radius)  b = (free stream U, source Q)    c.x = epsilon
//   downwash  a = (hub, radius)     b = (v_h, Q, ground, ground layer)
// Coordinates are the field's own (before its placement in the room), as for
// the baked grid. fieldEquation() returns nothing for fields it cannot express.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/field/analytic_field.h"

namespace sandstorm {

enum class EquationKind : int {
  Tornado = 1,
  Gravity = 2,
  Wind = 3,
  CurlNoise = 4,
  SphereFlow = 5,
  Downwash = 6
};

struct EquationTerm {
  EquationKind kind = EquationKind::Tornado;
  std::uint32_t seed =
      0;  // wind and curl noise: GradientNoise seed of the first channel (seed * 3)
  glm::vec4 a{0.0f}, b{0.0f}, c{0.0f};
};

struct FieldEquation {
  static constexpr int kMaxTerms = 4;
  std::vector<EquationTerm> terms;
};

std::optional<FieldEquation> fieldEquation(const AnalyticField& field);

}  // namespace sandstorm
