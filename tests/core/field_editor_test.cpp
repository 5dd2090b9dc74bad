// The field editor's core: each primitive against its closed form, the
// composition in a placed field, and the saved block reading back to the
// same primitives and the same composed grid.
#include <cmath>

#include <gtest/gtest.h>

#include "core/config/app_config.h"
#include "core/editor/field_composer.h"
#include "core/editor/field_editor_block.h"
#include "core/editor/primitive_field.h"
#include "core/field/analytic_field_factory.h"
#include "core/util/error.h"
#include "core/util/parallel_for.h"

namespace sandstorm {
namespace {

FieldPrimitive primitive(PrimitiveKind kind, glm::vec3 position, glm::vec3 axis, float strength,
                         float radius) {
  FieldPrimitive p;
  p.kind = kind;
  p.position = position;
  p.axis = axis;
  p.strength = strength;
  p.radius = radius;
  return p;
}

// Central-difference divergence of f at x (double steps of h).
double divergence(const AnalyticField& f, glm::vec3 x, float h) {
  double d = 0.0;
  for (int a = 0; a < 3; ++a) {
    glm::vec3 e(0.0f);
    e[a] = h;
    d += (double(f.evaluate(x + e)[a]) - double(f.evaluate(x - e)[a])) / (2.0 * h);
  }
  return d;
}

TEST(FieldEditor, AVortexSwirlsAboutItsAxisAtTheLambOseenSpeed) {
  // A tilted axis through (1, 2, 3), core 0.5 m, 4 m/s at the core radius.
  const glm::vec3 axis = glm::normalize(glm::vec3(1, 1, 2));
  const PrimitiveField f(primitive(PrimitiveKind::Vortex, {1, 2, 3}, axis * 3.0f, 4.0f, 0.5f));
  const glm::vec3 across = glm::normalize(glm::cross(axis, glm::vec3(0, 0, 1)));
  const double circulation = 2.0 * M_PI * 0.5 * 4.0 / (1.0 - std::exp(-1.0));
  for (float rho : {0.1f, 0.5f, 1.0f, 2.5f, 6.0f}) {
    for (float along : {-2.0f, 0.0f, 3.0f}) {
      const glm::vec3 x = glm::vec3(1, 2, 3) + along * axis + rho * across;
      const glm::vec3 v = f.evaluate(x);
      const double expected =
          circulation / (2.0 * M_PI * rho) * (1.0 - std::exp(-double(rho * rho) / 0.25));
      EXPECT_NEAR(glm::length(v), expected, 1e-5 * (1.0 + expected)) << rho;
      EXPECT_NEAR(glm::dot(v, axis), 0.0f, 1e-5f);             // no flow along the line
      EXPECT_NEAR(glm::dot(v, across), 0.0f, 1e-5f);           // none towards it
      EXPECT_GT(glm::dot(v, glm::cross(axis, across)), 0.0f);  // right-handed about the axis
    }
  }
  EXPECT_NEAR(glm::length(f.evaluate(glm::vec3(1, 2, 3) + 0.5f * across)), 4.0f, 1e-5f);
  EXPECT_EQ(f.evaluate(glm::vec3(1, 2, 3) + 2.0f * axis), glm::vec3(0.0f));  // on the axis
  for (const glm::vec3 x : {glm::vec3(1.3f, 2.1f, 2.9f), glm::vec3(-2, 0, 1), glm::vec3(2, 5, 3)})
    EXPECT_NEAR(divergence(f, x, 1e-2f), 0.0, 2e-3);
}

TEST(FieldEditor, ASourcePushesOutItsFluxAndASinkDrawsIn) {
  const PrimitiveField source(primitive(PrimitiveKind::Source, {0, 0, 2}, {0, 0, 1}, 3.0f, 0.5f));
  for (const glm::vec3 d : {glm::vec3(1, 0, 0), glm::normalize(glm::vec3(1, -2, 3))}) {
    for (float r : {0.25f, 0.5f, 1.0f, 4.0f}) {
      const glm::vec3 v = source.evaluate(glm::vec3(0, 0, 2) + r * d);
      const float expected = r >= 0.5f ? 3.0f * 0.25f / (r * r) : 3.0f * r / 0.5f;
      EXPECT_NEAR(glm::dot(v, d), expected, 1e-5f);
      EXPECT_NEAR(glm::length(v - glm::dot(v, d) * d), 0.0f, 1e-5f);
    }
  }
  // Outside the core the flow is divergence-free (the flux 4 pi R^2 S passes every sphere).
  EXPECT_NEAR(divergence(source, {1.5f, 0.7f, 2.4f}, 1e-2f), 0.0, 2e-3);
  const PrimitiveField sink(primitive(PrimitiveKind::Source, {0, 0, 2}, {0, 0, 1}, -3.0f, 0.5f));
  EXPECT_LT(sink.evaluate({2, 0, 2}).x, 0.0f);
  const PrimitiveField wind(primitive(PrimitiveKind::Wind, {9, 9, 9}, {0, 3, 4}, 5.0f, 1.0f));
  const glm::vec3 w = wind.evaluate({-3, 1, 7});
  EXPECT_NEAR(w.y, 3.0f, 1e-6f);
  EXPECT_NEAR(w.z, 4.0f, 1e-6f);
}

TEST(FieldEditor, LibraryFieldsTakeThePrimitivesNumbers) {
  // The sphere: the potential flow of a stream of 2 m/s along +y past a sphere of 1.5 m.
  const PrimitiveField sphere(
      primitive(PrimitiveKind::SphereFlow, {1, 1, 3}, {0, 2, 0}, 2.0f, 1.5f));
  const glm::vec3 far = sphere.evaluate({1, 1 + 200.0f, 3});
  EXPECT_NEAR(far.y, 2.0f, 1e-3f);
  const glm::vec3 top = sphere.evaluate({1, 1, 3 + 1.5f});  // the stream's shoulder: 1.5 U
  EXPECT_NEAR(top.y, 3.0f, 1e-3f);
  // The tornado: spin at the core radius, as VortexField with the same numbers says.
  const PrimitiveField tornado(primitive(PrimitiveKind::Tornado, {0, 0, 0}, {0, 0, 1}, 6.0f, 0.6f));
  const auto library = makeAnalyticField("tornado", {{"core", 0.6}, {"spin", 6.0}});
  const glm::vec3 x(0.6f, 0.0f, 1.0f);
  EXPECT_NEAR(glm::length(tornado.evaluate(x) - library->evaluate(x)), 0.0f, 1e-5f);
  // Empty and disabled slots add nothing.
  FieldPrimitive off = primitive(PrimitiveKind::Wind, {}, {1, 0, 0}, 5.0f, 1.0f);
  off.enabled = false;
  EXPECT_EQ(PrimitiveField(off).evaluate({1, 2, 3}), glm::vec3(0.0f));
  EXPECT_EQ(PrimitiveField(FieldPrimitive{}).evaluate({1, 2, 3}), glm::vec3(0.0f));
}

TEST(FieldEditor, TheComposedFieldIsTheBasePlusThePrimitivesInTheRoom) {
  // A placed field: turned 90 degrees about z, half size, moved.
  const auto base = makeAnalyticField("tornado", {});
  const VectorField grid = bake(*base, Box{{-4, -4, 0}, {4, 4, 6}}, {17, 15, 9});
  FieldPlacement placement;
  placement.offset = {1.0f, -2.0f, 0.5f};
  placement.scale = 0.5f;
  placement.rotation = glm::mat3(0, 1, 0, -1, 0, 0, 0, 0, 1);
  const std::vector<FieldPrimitive> primitives = {
      primitive(PrimitiveKind::Vortex, {1, -1, 1}, {0, 1, 1}, 3.0f, 0.4f), FieldPrimitive{},
      primitive(PrimitiveKind::Wind, {}, {1, 0, 0}, 2.0f, 1.0f),
      primitive(PrimitiveKind::Source, {0, -2, 2}, {}, -1.0f, 0.3f)};
  const VectorField composed = composeField(grid, placement, primitives);
  ParallelFor pool(3);
  const VectorField threaded = composeField(grid, placement, primitives, &pool);
  ASSERT_EQ(composed.dims(), grid.dims());
  for (int k = 0; k < 9; ++k)
    for (int j = 0; j < 15; ++j)
      for (int i = 0; i < 17; ++i) {
        // What a particle at that room point feels: the base carried to the room, plus the sum.
        const glm::vec3 room = placement.toRoom(grid.pointPosition(i, j, k));
        glm::vec3 expected = placement.vectorToRoom(grid.at(i, j, k));
        for (const FieldPrimitive& p : primitives)
          expected += PrimitiveField(p).evaluate(room);
        const glm::vec3 felt = placement.vectorToRoom(composed.at(i, j, k));
        ASSERT_NEAR(glm::length(felt - expected), 0.0f, 1e-4f * (1.0f + glm::length(expected)));
        ASSERT_EQ(threaded.at(i, j, k), composed.at(i, j, k));  // threads change nothing
      }
  // Nothing active: the base itself.
  const VectorField same = composeField(grid, placement, std::vector<FieldPrimitive>(8));
  EXPECT_TRUE(std::equal(same.values().begin(), same.values().end(), grid.values().begin()));
}

const std::string kWall =
    "[[wall]]\nname = \"w\"\ncamera = { position = [0, -8, 2], target = [0, 0, 2], fov_deg = 60 "
    "}\noffscreen = { size = [64, 64] }\n";

TEST(FieldEditor, TheSavedBlockReadsBackToTheSameFieldAndPrimitives) {
  AppConfig c = parseConfig(
      "[field]\nsource = \"analytic\"\nname = \"still\"\ndims = [9, 8, 7]\n"
      "bounds_min = [-3, -2.5, 0]\nbounds_max = [3.3, 2, 4.1]\noffset = [0.1, 0.2, 0.3]\n"
      "scale = 1.7\nrotation_deg = [10, 0, 33.3]\n"
      "[[primitive]]\nkind = \"vortex\"\nposition = [0.1, 0.7, 1.3]\naxis = [0.3, -1, 2]\n"
      "strength = 3.3\nradius = 0.45\n"
      "[[primitive]]\nkind = \"curl_noise\"\nstrength = 0.7\nradius = 1.9\nenabled = false\n" +
          kWall,
      "test.toml");
  c.particles.primitives[5] =
      primitive(PrimitiveKind::Source, {1.0f / 3.0f, -0.2f, 2.0f}, {}, -2.25f, 0.31f);
  const std::string block = fieldEditorBlock(c.field, c.particles.primitives);
  const AppConfig back = parseConfig(block + kWall, "back.toml");
  // Every slot comes back as it was, the empty ones between too.
  EXPECT_EQ(back.particles.primitives, c.particles.primitives);
  EXPECT_EQ(block.find("[[primitive]]", block.rfind("kind = \"source\"")), std::string::npos);
  EXPECT_EQ(back.field.source, "analytic");
  EXPECT_EQ(back.field.name, "still");
  EXPECT_EQ(back.field.dims, c.field.dims);
  EXPECT_EQ(back.field.bounds.min, c.field.bounds.min);
  EXPECT_EQ(back.field.bounds.max, c.field.bounds.max);
  EXPECT_EQ(back.field.placement.offset, c.field.placement.offset);
  EXPECT_EQ(back.field.placement.scale, c.field.placement.scale);
  EXPECT_EQ(back.field.placement.rotation, c.field.placement.rotation);
  // The same grid, bit for bit.
  const auto still = makeAnalyticField("still", {});
  const VectorField a = composeField(bake(*still, c.field.bounds, c.field.dims), c.field.placement,
                                     c.particles.primitives);
  const VectorField b = composeField(bake(*still, back.field.bounds, back.field.dims),
                                     back.field.placement, back.particles.primitives);
  EXPECT_GT(a.maxMagnitude(), 0.5f);
  EXPECT_TRUE(std::equal(a.values().begin(), a.values().end(), b.values().begin()));
}

TEST(FieldEditor, BadPrimitiveTablesNameTheLineAndKey) {
  const auto errorOf = [](const std::string& text) {
    try {
      parseConfig(text + kWall, "test.toml");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(errorOf("[[primitive]]\nstrength = 2\n").find("test.toml:1: primitive.0.kind: missing"),
            std::string::npos);
  EXPECT_EQ(errorOf("[[primitive]]\nkind = \"none\"\n"), "(no error)");  // an empty slot
  EXPECT_NE(errorOf("[[primitive]]\nkind = \"swirl\"\n").find("test.toml:2"), std::string::npos);
  EXPECT_NE(errorOf("[[primitive]]\nkind = \"wind\"\nradius = -1\n").find("primitive.0.radius"),
            std::string::npos);
  EXPECT_NE(errorOf("[[primitive]]\nkind = \"wind\"\nspeed = 1\n").find("primitive.0.speed"),
            std::string::npos);
  std::string nine;
  for (int i = 0; i < 9; ++i)
    nine += "[[primitive]]\nkind = \"wind\"\n";
  EXPECT_NE(errorOf(nine).find("at most 8 primitives"), std::string::npos);
}

}  // namespace
}  // namespace sandstorm
