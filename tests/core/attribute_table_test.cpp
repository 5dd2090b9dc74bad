#include "core/sim/attribute_table.h"

#include <gtest/gtest.h>

#include <set>

#include "core/util/error.h"

namespace sandstorm {
namespace {

const AttributeTable& table() {
  return AttributeTable::instance();
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(AttributeTable, AMistypedKeyOrChoiceIsAnsweredWithTheNameMeant) {
  EXPECT_NE(errorOf([&] {
              table().lookup("render.sise");
            }).find("unknown attribute 'render.sise' (did you mean 'render.size'?)"),
            std::string::npos);
  // An emitter's key keeps the emitter typed.
  EXPECT_NE(
      errorOf([&] { table().lookup("emitter.3.rat"); }).find("(did you mean 'emitter.3.rate'?)"),
      std::string::npos)
      << errorOf([&] { table().lookup("emitter.3.rat"); });
  EXPECT_NE(errorOf([&] {
              table().parse("render.color_by", "spead");
            }).find("cannot read 'spead' (did you mean 'speed'?) as one of the listed choices"),
            std::string::npos)
      << errorOf([&] { table().parse("render.color_by", "spead"); });
  EXPECT_EQ(errorOf([&] { table().parse("render.color_by", "temperature"); }).find("did you mean"),
            std::string::npos);
}

TEST(AttributeTable, EveryEntryIsDocumentedAndItsDefaultIsInRange) {
  std::set<std::string> keys;
  for (const AttributeInfo& info : table().entries()) {
    EXPECT_TRUE(keys.insert(info.key).second) << "duplicate " << info.key;
    EXPECT_FALSE(info.description.empty()) << info.key;
    const AttributeResult r = table().validate(info.itemKey(0), info.defaultValue);
    EXPECT_TRUE(r.warning.empty()) << info.key << ": " << r.warning;
  }
  // The thesis's Table 5.1 is covered.
  for (const char* thesis : {"Size", "Lifetime", "AreaWidth", "AreaDepth", "Maximum", "Position"})
    EXPECT_NO_THROW(table().lookup(thesis)) << thesis;
}

TEST(AttributeTable, SetsAndGetsThroughTheTable) {
  ParticleState s;
  table().set(s, "render.size", 0.25f);
  EXPECT_FLOAT_EQ(s.render.size, 0.25f);
  table().set(s, "AreaWidth", 3.0f);
  EXPECT_FLOAT_EQ(s.emitters[0].width, 3.0f);
  table().set(s, "sim.integrator", std::string("rk4"));
  EXPECT_EQ(s.sim.integrator, Integrator::RK4);
  EXPECT_EQ(std::get<std::string>(table().get(s, "sim.integrator")), "rk4");
  table().set(s, "emitter.0.position", glm::vec3(1, 2, 3));
  EXPECT_EQ(s.emitters[0].position, glm::vec3(1, 2, 3));
  table().set(s, "sim.maximum", 5000.0f);  // integral floats are accepted for ints
  EXPECT_EQ(s.sim.maximum, 5000);
}

// [field_playback] speed = 3 in a file and --set field_playback.speed=3 on
// the command line name the same attribute, field.speed.
TEST(AttributeTable, TheConfigurationsPlaybackTableNamesTheFieldsPlaybackAttributes) {
  ParticleState s;
  table().set(s, "field_playback.speed", 3.0f);
  EXPECT_FLOAT_EQ(s.field.speed, 3.0f);
  EXPECT_EQ(table().canonical("field_playback.loop"), "field.loop");
  EXPECT_NE(errorOf([] { table().lookup("field_playback.sped"); }).find("field.speed"),
            std::string::npos);
}

TEST(AttributeTable, ClampsOutOfRangeValuesAndSaysSo) {
  ParticleState s;
  const AttributeResult r = table().set(s, "render.opacity_birth", 3.0f);
  EXPECT_FLOAT_EQ(s.render.opacityBirth, 1.0f);
  EXPECT_NE(r.warning.find("render.opacity_birth"), std::string::npos) << r.warning;
  EXPECT_NE(r.warning.find("clamped to 1"), std::string::npos) << r.warning;
  const AttributeResult v = table().set(s, "sim.gravity", glm::vec3(0, 0, -500));
  EXPECT_EQ(s.sim.gravity, glm::vec3(0, 0, -100));
  EXPECT_FALSE(v.warning.empty());
  EXPECT_TRUE(table().set(s, "render.size", 0.5f).warning.empty());
}

TEST(AttributeTable, RefusesWrongTypesUnknownKeysAndChoices) {
  ParticleState s;
  const ParticleState before = s;
  EXPECT_NE(
      errorOf([&] { table().set(s, "render.size", std::string("big")); }).find("expected a number"),
      std::string::npos);
  EXPECT_NE(errorOf([&] { table().set(s, "sim.maximum", 2.5f); }).find("integer"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { table().set(s, "render.sise", 1.0f); }).find("render.size"),
            std::string::npos);  // suggests the near key
  EXPECT_NE(errorOf([&] {
              table().set(s, "sim.integrator", std::string("rk3"));
            }).find("euler, rk2, rk4"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { table().set(s, "emitter.5.rate", 1.0f); }).find("no emitter 5"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { table().set(s, "emitter.x.rate", 1.0f); }).find("emitter.N"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { table().set(s, "render.size", std::nanf("")); }).find("not finite"),
            std::string::npos);
  // A direction of no length (the slice's normal), however it is set.
  EXPECT_NE(errorOf([&] {
              table().set(s, "slice.normal", glm::vec3(0.0f));
            }).find("expected a direction, not (0, 0, 0)"),
            std::string::npos);
  EXPECT_EQ(s.render.size, before.render.size);
  EXPECT_EQ(s.sim.maximum, before.sim.maximum);
  EXPECT_EQ(s.slice.normal, before.slice.normal);
  table().set(s, "slice.normal", glm::vec3(0.0f, 0.0f, -0.5f));  // any length but 0
  EXPECT_EQ(s.slice.normal, glm::vec3(0.0f, 0.0f, -0.5f));
}

TEST(AttributeTable, ParsesText) {
  EXPECT_EQ(std::get<float>(table().parse("emitter.0.rate", "50000")), 50000.0f);
  EXPECT_EQ(std::get<int>(table().parse("sim.maximum", "1e6")), 1000000);
  EXPECT_EQ(std::get<bool>(table().parse("sim.paused", "true")), true);
  EXPECT_EQ(std::get<glm::vec3>(table().parse("emitter.0.velocity", "1, -2 3.5")),
            glm::vec3(1, -2, 3.5f));
  EXPECT_EQ(std::get<std::string>(table().parse("render.mode", "points")), "points");
  EXPECT_THROW(table().parse("emitter.0.velocity", "1 2"), Error);
  EXPECT_THROW(table().parse("emitter.0.velocity", "1 2 3 4"), Error);
  EXPECT_THROW(table().parse("emitter.0.rate", "12abc"), Error);
  EXPECT_THROW(table().parse("sim.paused", "maybe"), Error);
  EXPECT_THROW(table().parse("sim.maximum", "1.5"), Error);
}

// A number beyond its type (a float's 3.4e38, an integer's 2e9) is refused as
// outside the attribute's range, quoted as written: not "cannot read" (it is
// a number), nor reported as the number it was first clamped to.
TEST(AttributeTable, NumbersBeyondTheirTypeAreOutsideTheRangeAsWritten) {
  const auto message = [](const char* key, const char* text) {
    try {
      table().parse(key, text);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("sim.maximum", "99999999999"),
            "attribute 'sim.maximum': 99999999999 is outside [0, 1e+08] particles");
  EXPECT_EQ(message("render.size", "1e40"),
            "attribute 'render.size': 1e40 is outside [1e-07, 1000] m");
  EXPECT_EQ(message("render.size", "-1e400"),
            "attribute 'render.size': -1e400 is outside [1e-07, 1000] m");
  EXPECT_NE(message("render.size", "1e40x").find("cannot read '1e40x' as a number"),
            std::string::npos);
  EXPECT_NE(message("render.size", "nan").find("cannot read 'nan' as a number"), std::string::npos);
  // Closer to 0 than a float (or a double) holds is 0 (then judged by the range).
  EXPECT_EQ(std::get<float>(table().parse("render.shutter", "1e-50")), 0.0f);
  EXPECT_EQ(std::get<float>(table().parse("render.shutter", "-1e-400")), 0.0f);
  EXPECT_EQ(std::get<int>(table().parse("sim.maximum", "1e-400")), 0);
  EXPECT_EQ(std::get<int>(table().parse("sim.maximum", " +12e3 ")), 12000);
  EXPECT_NE(message("sim.maximum", "1e-5").find("cannot read '1e-5' as an integer"),
            std::string::npos);
}

}  // namespace
}  // namespace sandstorm
