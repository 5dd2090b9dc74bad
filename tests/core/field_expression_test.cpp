// Fields written at run time (core/expr): muParser's values, the GLSL
// translation's shape, every bad text refused with its place, the attribute
// refusing whole, and particles moved by an expression as the analytic flow
// it writes moves them.
#include <gtest/gtest.h>

#include <cmath>

#include "core/config/app_config.h"
#include "core/expr/expression_glsl.h"
#include "core/expr/field_expression.h"
#include "core/field/vortex_field.h"
#include "core/sim/attribute_table.h"
#include "core/sim/reference_simulator.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

std::string refusal(const std::array<std::string, 3>& text) {
  try {
    FieldExpression::compile(text);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(FieldExpression, EvaluatesTheVariablesAsMuParserDoes) {
  const auto e = FieldExpression::compile(
      {"-y + 0*t", "x * (age < 1 ? 1 : 2)", "0.1 + 0.05*x + vx^2 - sqrt(abs(vz)) + min(t, 3, 1)"});
  const glm::vec3 f = e->evaluate({2, 3, 4}, 5.0f, {-2, 0, -4}, 0.5f);
  EXPECT_FLOAT_EQ(f.x, -3.0f);
  EXPECT_FLOAT_EQ(f.y, 2.0f);
  EXPECT_FLOAT_EQ(f.z, 0.1f + 0.1f + 4.0f - 2.0f + 1.0f);
  EXPECT_FLOAT_EQ(e->evaluate({2, 3, 4}, 5.0f, {}, 1.5f).y, 4.0f);  // age past 1
}

TEST(FieldExpression, TheGlslKeepsMuParsersPrecedenceAndMeanings) {
  // -2^2 is -(2^2), 2^3^2 is 2^(3^2): the tree, written out with parentheses.
  EXPECT_EQ(expressionToGlsl("-x^2"), "(-e_pow(e_x, 2.0))");
  EXPECT_EQ(expressionToGlsl("2^3^2"), "e_pow(2.0, e_pow(3.0, 2.0))");
  EXPECT_EQ(expressionToGlsl("1 - 2 - 3"), "((1.0 - 2.0) - 3.0)");
  EXPECT_EQ(expressionToGlsl("x < 1 ? y : z"), "((e_x < 1.0 ? 1.0 : 0.0) != 0.0 ? e_y : e_z)");
  EXPECT_EQ(expressionToGlsl("ln(x) + log10(y)"), "(log(e_x) + (log(e_y) * 0.434294481903251828))");
  EXPECT_EQ(expressionToGlsl("max(x, y, z)"), "max(max(e_x, e_y), e_z)");
  EXPECT_EQ(expressionToGlsl("avg(x, y)"), "((e_x + e_y) / 2.0)");
  EXPECT_EQ(expressionToGlsl("_pi"), "3.141592653589");  // muParser's own digits
}

TEST(FieldExpression, EveryBadTextIsRefusedWithTheComponentAndThePlace) {
  struct Case {
    std::string text, says;
  };
  for (const Case& c : std::vector<Case>{
           {"x +", "x component 'x +': at the end:"},
           {"sin(x", "at the end: Missing parenthesis"},
           {"foo(x)", "at 0: Unexpected token \"foo\""},
           {"1, 2", "expected one"},
           {"x $ 2", "at 2:"},
           {"2 % 3", "at 2:"},
           {"", "at the end: Expression is empty"},
           {"a = 2", "at 0:"},
           {"(x", "at the end:"},
           {"atan2(x)", "at "},
           {"x y", "at 2:"},
           {"1e40 * x", "beyond a float's range"},
       }) {
    SCOPED_TRACE(c.text);
    const std::string message = refusal({c.text, "0", "0"});
    EXPECT_NE(message.find(c.says), std::string::npos) << message;
    EXPECT_NE(message.find("x component"), std::string::npos) << message;
  }
  EXPECT_NE(refusal({"0", "0", "sqrt("}).find("z component"), std::string::npos);
  EXPECT_NE(refusal({std::string(300, 'x'), "0", "0"}).find("longer than 256"), std::string::npos);
}

TEST(FieldExpression, TheAttributeRefusesABadTextWholeAndKeepsTheGoodOne) {
  const AttributeTable& table = AttributeTable::instance();
  ParticleState s;
  table.set(s, "field.expression_x", std::string("-y"));
  EXPECT_EQ(s.field.expression[0], "-y");
  EXPECT_THROW(table.set(s, "field.expression_x", std::string("-y +")), Error);
  EXPECT_EQ(s.field.expression[0], "-y");  // nothing half-applied
  try {
    table.set(s, "field.expression_y", std::string("cos(t"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("attribute 'field.expression_y': y component"),
              std::string::npos)
        << e.what();
  }
  // One word in sessions and --set: spaces as %20.
  EXPECT_EQ(std::get<std::string>(table.parse("field.expression_z", "0.1%20+%20x")), "0.1 + x");
  EXPECT_EQ(encodeName("0.1 + x"), "0.1%20+%20x");
  table.set(s, "field.mode", std::string("expression"));
  EXPECT_EQ(s.field.mode, FieldMode::Expression);
}

TEST(FieldExpression, ParticlesInASolidBodyRotationWrittenAsAnExpressionGoRoundCircles) {
  // v = (-y, x, 0.2): circles of unchanged radius at 1 rad/s, rising 0.2 m/s.
  ParticleState s;
  s.field.mode = FieldMode::Expression;
  s.field.expression = {"-y", "x", "0.2"};
  s.sim.integrator = Integrator::RK4;
  s.sim.boundary = BoundaryMode::Clamp;
  s.sim.maximum = 1000;
  Emitter& e = s.emitters[0];
  e.shape = EmitterShape::Disc;
  e.position = {0, 0, 1};
  e.radius = 2.0f;
  e.lifetime = 100.0f;
  auto field = std::make_shared<VectorField>(Box{{-5, -5, 0}, {5, 5, 10}}, glm::ivec3(2),
                                             std::vector<glm::vec3>(8, glm::vec3(0.0f)));
  ReferenceSimulator sim(1000);
  sim.setField(field);
  const float dt = 1.0f / 60.0f;
  sim.step(SimStep{0, dt, Seed::from(1), {500}, 0.0f, 0.0}, s);
  std::vector<Particle> start(sim.particles().begin(), sim.particles().end());
  for (int f = 1; f <= 120; ++f)
    sim.step(SimStep{std::uint32_t(f), dt, Seed::from(1), {0}, 0.0f, f * double(dt)}, s);
  ASSERT_EQ(sim.particles().size(), start.size());
  const float turned = 120 * dt;  // 2 s at 1 rad/s
  for (std::size_t i = 0; i < start.size(); ++i) {
    const glm::vec3 a = start[i].position(), b = sim.particles()[i].position();
    const glm::vec3 expected(a.x * std::cos(turned) - a.y * std::sin(turned),
                             a.x * std::sin(turned) + a.y * std::cos(turned), a.z + 0.2f * turned);
    EXPECT_LT(glm::length(b - expected), 1e-4f) << i;
  }
}

TEST(FieldExpression, AConfigurationWritesTheFieldAsThreeExpressions) {
  const std::string wall =
      "[[wall]]\nname = \"w\"\ncamera = {position = [0, -5, 1.7], target = [0, 0, 1]}\n"
      "offscreen = {size = [64, 48]}\n";
  const AppConfig c =
      parseConfig(wall + "[field]\nexpression = [\"-y\", \"x\", \"0.1 + 0.05*x\"]\n", "e.toml");
  EXPECT_EQ(c.particles.field.mode, FieldMode::Expression);
  EXPECT_EQ(c.particles.field.expression[2], "0.1 + 0.05*x");
  try {
    parseConfig(wall + "[field]\nexpression = [\"-y\", \"x +\", \"0\"]\n", "e.toml");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("e.toml:6: attribute 'field.expression_y': y component"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(parseConfig(wall + "[field]\nexpression = [\"-y\", \"x\"]\n", "e.toml"), Error);
}

}  // namespace
}  // namespace sandstorm
