// FieldExpression: a field written at run time, the thesis's "shader based
// physics model ... to change the behavior of the particles without having
// to recompile" (7.2): three expressions of x, y, z (the field's own
// coordinates, as a grid's points), t (simulated seconds), vx, vy, vz (the
// particle's velocity, m/s) and age (seconds it has lived), one a component.
// field.mode = expression moves particles by it in place of the grid, whose
// bounds still bound them (field.expression_x, _y, _z in the attribute table).
//
// The CPU evaluates it with muParser (double precision); the GPU runs the
// same expressions translated to GLSL (expression_glsl.h) in float, so the
// two agree to float rounding. Compiling checks both: a text either library
// refuses is refused whole, with the component, the position and what was
// expected.
#pragma once

#include <array>
#include <memory>
#include <string>

#include <glm/glm.hpp>

namespace sandstorm {

class FieldExpression {
 public:
  // Throws Error: "x component: at 4: Unexpected token ..." (the component,
  // the position from 0, the library's message).
  static std::shared_ptr<const FieldExpression> compile(const std::array<std::string, 3>& text);
  // Throws Error for one component's text alone ("x", "y" or "z" names it).
  static void check(const std::string& text, const char* component);

  glm::vec3 evaluate(const glm::vec3& p, float t, const glm::vec3& v, float age) const;
  const std::array<std::string, 3>& text() const { return text_; }
  const std::array<std::string, 3>& glsl() const { return glsl_; }

  FieldExpression(const FieldExpression&) = delete;
  FieldExpression& operator=(const FieldExpression&) = delete;
  ~FieldExpression();

 private:
  FieldExpression() = default;
  struct Parsers;
  std::array<std::string, 3> text_, glsl_;
  std::unique_ptr<Parsers> parsers_;
};

}  // namespace sandstorm
