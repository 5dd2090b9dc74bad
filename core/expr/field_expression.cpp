#include "core/expr/field_expression.h"

#include <muParser.h>

#include <cstddef>
#include <mutex>

#include "core/expr/expression_glsl.h"
#include "core/util/error.h"

namespace sandstorm {

// muParser reads its variables through pointers; evaluate() writes them under
// a lock, so one expression may be shared between threads.
struct FieldExpression::Parsers {
  std::array<mu::Parser, 3> parser;
  double x = 0, y = 0, z = 0, t = 0, vx = 0, vy = 0, vz = 0, age = 0;
  std::mutex mutex;

  void define(mu::Parser& p) {
    p.DefineVar("x", &x);
    p.DefineVar("y", &y);
    p.DefineVar("z", &z);
    p.DefineVar("t", &t);
    p.DefineVar("vx", &vx);
    p.DefineVar("vy", &vy);
    p.DefineVar("vz", &vz);
    p.DefineVar("age", &age);
  }
};

namespace {

// "at 4" (from 0), or "at the end": muParser counts past it, or -1.
std::string place(std::ptrdiff_t position, const std::string& text) {
  if (position < 0 || std::size_t(position) >= text.size()) return "at the end";
  return concat("at ", position);
}

// muParser's check, then ours (the GLSL translation); returns the GLSL.
std::string checked(mu::Parser& p, const std::string& text, const char* component) {
  const std::string where = concat(component, " component '", text, "'");
  if (text.size() > 256) throw Error(concat(where, ": longer than 256 characters"));
  try {
    p.SetExpr(text);
    p.Eval();  // compiles it; the variables' values do not matter here
    if (p.GetNumResults() != 1)
      throw Error(concat(where, ": ", p.GetNumResults(), " values separated by ','; expected one"));
  } catch (const mu::Parser::exception_type& e) {
    throw Error(concat(where, ": ", place(e.GetPos(), text), ": ", e.GetMsg()));
  }
  try {
    return expressionToGlsl(text);
  } catch (const ExpressionError& e) {
    throw Error(concat(where, ": ", place(std::ptrdiff_t(e.position), text), ": ", e.what()));
  }
}

}  // namespace

FieldExpression::~FieldExpression() = default;

void FieldExpression::check(const std::string& text, const char* component) {
  Parsers parsers;
  parsers.define(parsers.parser[0]);
  checked(parsers.parser[0], text, component);
}

std::shared_ptr<const FieldExpression> FieldExpression::compile(
    const std::array<std::string, 3>& text) {
  std::shared_ptr<FieldExpression> e(new FieldExpression);
  e->parsers_ = std::make_unique<Parsers>();
  e->text_ = text;
  const char* names[3] = {"x", "y", "z"};
  for (int c = 0; c < 3; ++c) {
    e->parsers_->define(e->parsers_->parser[std::size_t(c)]);
    e->glsl_[std::size_t(c)] =
        checked(e->parsers_->parser[std::size_t(c)], text[std::size_t(c)], names[c]);
  }
  return e;
}

glm::vec3 FieldExpression::evaluate(const glm::vec3& p, float t, const glm::vec3& v,
                                    float age) const {
  Parsers& s = *parsers_;
  std::lock_guard lock(s.mutex);
  s.x = p.x;
  s.y = p.y;
  s.z = p.z;
  s.t = t;
  s.vx = v.x;
  s.vy = v.y;
  s.vz = v.z;
  s.age = age;
  return {float(s.parser[0].Eval()), float(s.parser[1].Eval()), float(s.parser[2].Eval())};
}

}  // namespace sandstorm
