// ColorScale, FieldRange and ColorLegend against values worked out by hand.
#include <gtest/gtest.h>

#include <limits>

#include "core/color/color_grid.h"
#include "core/color/color_legend.h"
#include "core/color/color_scale.h"
#include "core/field/field_range.h"

namespace sandstorm {
namespace {

std::vector<std::string> labels(const ColorLegend& legend) {
  std::vector<std::string> out;
  for (const LegendTick& t : legend.ticks)
    out.push_back(t.label);
  return out;
}

TEST(ColorScale, MapsValuesLinearlyOrByTheirLogarithm) {
  ColorScale s{.quantity = ColorQuantity::Speed, .low = 2.0f, .high = 6.0f};
  EXPECT_FLOAT_EQ(s.coordinate(3.0f), 0.25f);
  EXPECT_FLOAT_EQ(s.coordinate(-10.0f), 0.0f);
  EXPECT_FLOAT_EQ(s.coordinate(10.0f), 1.0f);
  EXPECT_FLOAT_EQ(s.valueAt(0.75f), 5.0f);
  ColorScale log{.quantity = ColorQuantity::Speed, .low = 1.0f, .high = 100.0f, .log = true};
  EXPECT_NEAR(log.coordinate(10.0f), 0.5f, 1e-6f);
  EXPECT_NEAR(log.coordinate(0.0f), 0.0f, 1e-6f);
  EXPECT_NEAR(log.valueAt(0.5f), 10.0f, 1e-4f);
  ColorScale flat{.quantity = ColorQuantity::Speed, .low = 3.0f, .high = 3.0f};
  EXPECT_FLOAT_EQ(flat.coordinate(100.0f), 0.5f);
}

TEST(ColorScale, ParticleValuesAreAgeFractionSpeedAndComponents) {
  Particle p{glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), glm::vec4(3.0f, -4.0f, 12.0f, 4.0f)};
  EXPECT_FLOAT_EQ(colorValue(p, ColorQuantity::Age), 0.75f);  // 1 s of 4 left
  EXPECT_FLOAT_EQ(colorValue(p, ColorQuantity::Speed), 13.0f);
  EXPECT_FLOAT_EQ(colorValue(p, ColorQuantity::VelocityY), -4.0f);
  EXPECT_FLOAT_EQ(colorValue(p, ColorQuantity::VelocityZ), 12.0f);
}

TEST(FieldRange, CoversTheValidPointsOnly) {
  VectorField f(Box{glm::vec3(0.0f), glm::vec3(1.0f)}, glm::ivec3(2, 1, 1),
                {glm::vec3(3.0f, 4.0f, 0.0f), glm::vec3(-100.0f, 0.0f, 0.0f)});
  FieldRange all = FieldRange::of(f);
  EXPECT_FLOAT_EQ(all.minSpeed, 5.0f);
  EXPECT_FLOAT_EQ(all.maxSpeed, 100.0f);
  EXPECT_FLOAT_EQ(all.minVelocity.x, -100.0f);
  EXPECT_FLOAT_EQ(all.maxVelocity.y, 4.0f);
  f.setValidity({1, 0});
  FieldRange valid = FieldRange::of(f);
  EXPECT_FLOAT_EQ(valid.maxSpeed, 5.0f);
  EXPECT_FLOAT_EQ(valid.minVelocity.x, 3.0f);
}

TEST(ColorScale, TheFieldRangeOrTheFixedEndsBoundTheScale) {
  FieldRange field{.minSpeed = 0.5f,
                   .maxSpeed = 8.0f,
                   .minVelocity = glm::vec3(-1, -2, -3),
                   .maxVelocity = glm::vec3(1, 2, 3)};
  ColorScale s = resolveColorScale(ColorQuantity::Speed, ColorRange::Field, 0, 1, false, field);
  EXPECT_FLOAT_EQ(s.low, 0.5f);
  EXPECT_FLOAT_EQ(s.high, 8.0f);
  s = resolveColorScale(ColorQuantity::VelocityZ, ColorRange::Field, 0, 1, false, field);
  EXPECT_FLOAT_EQ(s.low, -3.0f);
  EXPECT_FLOAT_EQ(s.high, 3.0f);
  s = resolveColorScale(ColorQuantity::Age, ColorRange::Field, 5, 9, false, field);
  EXPECT_FLOAT_EQ(s.high, 1.0f);
  s = resolveColorScale(ColorQuantity::Speed, ColorRange::Fixed, 2, 4, false, field);
  EXPECT_FLOAT_EQ(s.low, 2.0f);
  EXPECT_FLOAT_EQ(s.high, 4.0f);
  EXPECT_TRUE(s.note.empty());
}

TEST(ColorScale, ALogScaleThatReachesZeroKeepsThreeDecadesAndSaysSo) {
  FieldRange field{.minSpeed = 0.0f, .maxSpeed = 8.0f};
  ColorScale s = resolveColorScale(ColorQuantity::Speed, ColorRange::Field, 0, 1, true, field);
  EXPECT_TRUE(s.log);
  EXPECT_FLOAT_EQ(s.low, 0.008f);
  EXPECT_NE(s.note.find("three decades"), std::string::npos) << s.note;
  s = resolveColorScale(ColorQuantity::VelocityX, ColorRange::Fixed, -5, -1, true, field);
  EXPECT_FALSE(s.log);
  EXPECT_NE(s.note.find("needs values above 0"), std::string::npos) << s.note;
}

TEST(ColorLegend, LinearTicksAreNiceNumbersInsideTheRange) {
  ColorScale s{.quantity = ColorQuantity::Speed, .low = 0.0f, .high = 7.99763f};
  ColorLegend legend = ColorLegend::of(s);
  EXPECT_EQ(legend.title, "speed (m/s)");
  EXPECT_EQ(labels(legend), (std::vector<std::string>{"0", "2", "4", "6"}));
  EXPECT_NEAR(legend.ticks[2].t, 4.0f / 7.99763f, 1e-6f);
  s.low = -3.0f;
  s.high = 3.0f;
  EXPECT_EQ(labels(ColorLegend::of(s)), (std::vector<std::string>{"-2", "0", "2"}));
  s.low = 0.013f;
  s.high = 0.0871f;
  EXPECT_EQ(labels(ColorLegend::of(s)), (std::vector<std::string>{"0.02", "0.04", "0.06", "0.08"}));
  s.quantity = ColorQuantity::Age;
  s.low = 0.0f;
  s.high = 1.0f;
  EXPECT_EQ(ColorLegend::of(s).title, "age (fraction of life)");
  EXPECT_EQ(labels(ColorLegend::of(s)),
            (std::vector<std::string>{"0.0", "0.2", "0.4", "0.6", "0.8", "1.0"}));
}

TEST(ColorLegend, LogTicksAreDecadesWithTwosAndFivesWhenFew) {
  ColorScale s{.quantity = ColorQuantity::Speed, .low = 1.0f, .high = 1000.0f, .log = true};
  ColorLegend legend = ColorLegend::of(s);
  EXPECT_EQ(labels(legend), (std::vector<std::string>{"1", "10", "100", "1000"}));
  EXPECT_NEAR(legend.ticks[1].t, 1.0f / 3.0f, 1e-5f);
  EXPECT_EQ(legend.title, "speed (m/s), log scale");
  s.low = 0.5f;
  s.high = 20.0f;
  EXPECT_EQ(labels(ColorLegend::of(s)),
            (std::vector<std::string>{"0.5", "1", "2", "5", "10", "20"}));
}

// A narrow range whose nice step leaves one tick (1.00 .. 1.044 with two
// asked for: a step of 0.05) gets a finer step and two or more; so does a log
// scale within one decade (no 1, 2 or 5 times a power of ten inside).
TEST(ColorLegend, ANarrowRangeStillHasTwoTicks) {
  ColorScale s{.quantity = ColorQuantity::Speed, .low = 1.0f, .high = 1.044f};
  EXPECT_EQ(labels(ColorLegend::of(s, 2)), (std::vector<std::string>{"1.00", "1.02", "1.04"}));
  s.low = 0.96f;
  s.high = 1.01f;
  EXPECT_EQ(labels(ColorLegend::of(s, 1)), (std::vector<std::string>{"0.96", "0.98", "1.00"}));
  s.low = 1.5f;
  s.high = 1.9f;
  s.log = true;
  const ColorLegend log = ColorLegend::of(s, 4);
  EXPECT_EQ(labels(log), (std::vector<std::string>{"1.5", "1.6", "1.7", "1.8", "1.9"}));
  EXPECT_NEAR(log.ticks[1].t, std::log(1.6f / 1.5f) / std::log(1.9f / 1.5f), 1e-5f);
  EXPECT_DOUBLE_EQ(smallerNiceStep(0.05), 0.02);
  EXPECT_DOUBLE_EQ(smallerNiceStep(0.02), 0.01);
  EXPECT_DOUBLE_EQ(smallerNiceStep(10.0), 5.0);
}

TEST(ColorLegend, AFlatRangeHasOneTickInTheMiddle) {
  ColorScale s{.quantity = ColorQuantity::Speed, .low = 2.5f, .high = 2.5f};
  ColorLegend legend = ColorLegend::of(s);
  ASSERT_EQ(legend.ticks.size(), 1u);
  EXPECT_FLOAT_EQ(legend.ticks[0].t, 0.5f);
  EXPECT_FLOAT_EQ(legend.ticks[0].value, 2.5f);
}

}  // namespace
}  // namespace sandstorm

#include "core/field/analytic_field.h"
#include "core/field/vorticity.h"
#include "core/sim/attribute_table.h"
#include "core/sim/main_context.h"
#include "core/sim/session_log.h"
#include "core/sim/state_color_scale.h"
#include "core/sim/state_mirror.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

struct Spin final : AnalyticField {  // solid-body rotation, 1 rad/s: vorticity 2
  glm::vec3 evaluate(const glm::vec3& p) const override { return {-p.y, p.x, 0.0f}; }
};
struct Shear final : AnalyticField {  // v = (0, 3x, 0): vorticity 3
  glm::vec3 evaluate(const glm::vec3& p) const override { return {0.0f, 3.0f * p.x, 0.0f}; }
};

TEST(Vorticity, IsTwiceTheRotationRateAndTheShearRate) {
  const VectorField spin = vorticityMagnitude(bake(Spin(), Box{{-2, -2, 0}, {2, 2, 1}}, {5, 5, 2}));
  for (const glm::vec3& w : spin.values())
    EXPECT_NEAR(w.x, 2.0f, 1e-5f);  // edges too (one-sided)
  const VectorField shear =
      vorticityMagnitude(bake(Shear(), Box{{-2, -2, 0}, {2, 2, 1}}, {5, 3, 1}));
  for (const glm::vec3& w : shear.values())
    EXPECT_NEAR(w.x, 3.0f, 1e-5f);  // a flat grid
  VectorField masked = bake(Spin(), Box{{-2, -2, 0}, {2, 2, 1}}, {5, 5, 2});
  std::vector<std::uint8_t> valid(masked.pointCount(), 1);
  valid[masked.index(1, 2, 0)] = 0;
  masked.setValidity(valid);
  const VectorField w = vorticityMagnitude(masked);
  EXPECT_FALSE(w.valid(1, 2, 0));
  EXPECT_NEAR(w.at(2, 2, 0).x, 2.0f, 1e-5f);  // one-sided next to the hole: still exact
  // No neighbour with data along x: dv/dx counts as 0, leaving -du/dy = 1.
  EXPECT_NEAR(w.at(0, 2, 0).x, 1.0f, 1e-5f);
}

TEST(ColorScale, TheFieldsRangeIsScaledAsTheParticlesFeelIt) {
  FieldRange field{.minSpeed = 1.0f,
                   .maxSpeed = 8.0f,
                   .minVelocity = glm::vec3(-1, -2, -3),
                   .maxVelocity = glm::vec3(1, 2, 4),
                   .minScalar = 0.5f,
                   .maxScalar = 6.0f};
  // Strength 2, placement scale 0.25: velocities x0.5, vorticity x2.
  const FieldFeel feel{0.5f, 2.0f};
  ColorScale s =
      resolveColorScale(ColorQuantity::Speed, ColorRange::Field, 0, 1, false, field, feel);
  EXPECT_FLOAT_EQ(s.high, 4.0f);
  s = resolveColorScale(ColorQuantity::Vorticity, ColorRange::Field, 0, 1, false, field, feel);
  EXPECT_FLOAT_EQ(s.low, 1.0f);
  EXPECT_FLOAT_EQ(s.high, 12.0f);
  // A negative strength turns velocities round: the component range flips.
  s = resolveColorScale(ColorQuantity::VelocityZ, ColorRange::Field, 0, 1, false, field,
                        {-1.0f, -1.0f});
  EXPECT_FLOAT_EQ(s.low, -4.0f);
  EXPECT_FLOAT_EQ(s.high, 3.0f);
  // Components are the particles' axes: a quarter turn about z makes field x room y.
  const VectorField wind = bake(Shear(), Box{{0, 0, 0}, {1, 1, 1}}, {2, 2, 2});  // v = (0, 3x, 0)
  const FieldRange turned = FieldRange::of(wind, glm::mat3(0, 1, 0, -1, 0, 0, 0, 0, 1));
  EXPECT_FLOAT_EQ(turned.minVelocity.x, -3.0f);
  EXPECT_FLOAT_EQ(turned.maxVelocity.y, 0.0f);
}

TEST(MainContextVorticity, TheFieldCarriesItsVorticityWhileParticlesAreColouredByIt) {
  auto field = std::make_shared<VectorField>(bake(Spin(), Box{{-2, -2, 0}, {2, 2, 1}}, {5, 5, 2}));
  MainContext main(ParticleState{}, FieldUpdate{.field = field}, {});
  FramePacket first = main.next();
  ASSERT_TRUE(first.fieldUpdate);
  EXPECT_FALSE(first.fieldUpdate->colorGrid);
  main.set("render.color_by", std::string("vorticity"));
  const FramePacket later = main.next();  // the change and the field, with its vorticity
  ASSERT_TRUE(later.fieldUpdate) << "the field goes again, with its vorticity";
  ASSERT_TRUE(later.fieldUpdate->colorGrid);
  EXPECT_EQ(later.fieldUpdate->field, field);  // the same grid: walls do not upload it again
  EXPECT_NEAR(later.fieldUpdate->range.maxScalar, 2.0f, 1e-5f);
  EXPECT_FALSE(main.next().fieldUpdate);  // once
  main.set("render.color_by", std::string("speed"));
  const FramePacket off = main.next();
  ASSERT_TRUE(off.fieldUpdate);
  EXPECT_FALSE(off.fieldUpdate->colorGrid);
}

// A field with a validity mask and two scalar arrays, one with a NaN.
std::shared_ptr<VectorField> withArrays() {
  auto field = std::make_shared<VectorField>(bake(Spin(), Box{{-2, -2, 0}, {2, 2, 1}}, {3, 2, 2}));
  std::vector<float> t(field->pointCount()), p(field->pointCount(), 1.0f);
  for (std::size_t i = 0; i < t.size(); ++i)
    t[i] = 300.0f + float(i);
  t[5] = std::numeric_limits<float>::quiet_NaN();
  std::vector<std::uint8_t> valid(field->pointCount(), 1);
  valid[11] = 0;  // the largest temperature, 311, lies outside the data
  field->setValidity(valid);
  field->addScalars("temperature", t);
  field->addScalars("pressure", p);
  return field;
}

TEST(ColorGrid, AnArraysGridHoldsItsValuesAndTheFieldsValidity) {
  const auto field = withArrays();
  const auto grid = scalarGrid(*field, "temperature");
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->dims(), field->dims());
  EXPECT_EQ(grid->values()[3], glm::vec3(303.0f, 0.0f, 0.0f));
  EXPECT_EQ(grid->invalidCount(), 1u);
  EXPECT_FALSE(scalarGrid(*field, "density"));
  // The range skips the point without data and the NaN.
  const FieldRange range = FieldRange::of(*field, glm::mat3(1.0f), grid.get());
  EXPECT_EQ(range.minScalar, 300.0f);
  EXPECT_EQ(range.maxScalar, 310.0f);
}

TEST(ColorGrid, TheQuantityNamesTheGridItNeeds) {
  const auto field = withArrays();
  const VectorField bare(Box{{0, 0, 0}, {1, 1, 1}}, {2, 2, 2});
  EXPECT_EQ(colorGridName(ColorQuantity::Speed, "", *field), std::nullopt);
  EXPECT_EQ(colorGridName(ColorQuantity::Vorticity, "pressure", *field), std::string());
  EXPECT_EQ(colorGridName(ColorQuantity::Array, "pressure", *field), std::string("pressure"));
  EXPECT_EQ(colorGridName(ColorQuantity::Array, "", *field), std::string("temperature"));
  EXPECT_EQ(colorGridName(ColorQuantity::Array, "density", *field), std::nullopt);
  EXPECT_EQ(colorGridName(ColorQuantity::Array, "", bare), std::nullopt);
}

TEST(MainContextArrays, TheFieldCarriesTheChosenArrayAndTheLegendNamesIt) {
  const auto field = withArrays();
  MainContext main(ParticleState{}, FieldUpdate{.field = field}, {});
  main.next();
  main.set("render.color_by", std::string("array"));  // no name: the first array
  FramePacket p = main.next();
  ASSERT_TRUE(p.fieldUpdate && p.fieldUpdate->colorGrid);
  EXPECT_EQ(p.fieldUpdate->colorArray, "temperature");
  EXPECT_EQ(p.fieldUpdate->range.maxScalar, 310.0f);
  ParticleState state = main.state();
  const ColorScale scale = stateColorScale(state, p.fieldUpdate.get());
  EXPECT_EQ(scale.low, 300.0f);
  EXPECT_EQ(scale.high, 310.0f);
  EXPECT_EQ(ColorLegend::of(scale).title, "temperature");
  main.set("render.color_array", std::string("pressure"));
  p = main.next();
  ASSERT_TRUE(p.fieldUpdate && p.fieldUpdate->colorGrid);
  EXPECT_EQ(p.fieldUpdate->colorArray, "pressure");
  EXPECT_EQ(p.fieldUpdate->colorGrid->values()[0].x, 1.0f);
  EXPECT_FALSE(main.next().fieldUpdate);  // once
}

TEST(MainContextArrays, AnArrayTheFieldLacksIsRefusedNamingThoseItHas) {
  MainContext main(ParticleState{}, FieldUpdate{.field = withArrays()}, {});
  main.next();
  try {
    main.set("render.color_array", std::string("density"));
    main.set("render.color_by", std::string("array"));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no scalar array 'density'; its arrays: 'temperature', "
                                         "'pressure'"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(main.pendingState().render.colorBy, ColorQuantity::Age);  // nothing half-applied
  MainContext bare(ParticleState{},
                   FieldUpdate{.field = std::make_shared<VectorField>(Box{{0, 0, 0}, {1, 1, 1}},
                                                                      glm::ivec3(2, 2, 2))},
                   {});
  EXPECT_THROW(bare.set("render.color_by", std::string("array")), Error);
}

TEST(AttributeTableNames, ANameIsPrintableWordsAndTravelsAsOneWord) {
  const AttributeTable& table = AttributeTable::instance();
  ParticleState s;
  table.set(s, "render.color_array", table.parse("render.color_array", "Temperature_K"));
  EXPECT_EQ(s.render.colorArray, "Temperature_K");
  EXPECT_EQ(toString(table.get(s, "render.color_array")), "Temperature_K");
  // ParaView users' arrays have spaces: as typed, and as one word (%20).
  for (const char* typed : {"Pressure (Pa)", "Pressure%20(Pa)"}) {
    table.set(s, "render.color_array", table.parse("render.color_array", typed));
    EXPECT_EQ(s.render.colorArray, "Pressure (Pa)") << typed;
  }
  EXPECT_EQ(encodeName("Pressure (Pa)"), "Pressure%20(Pa)");
  EXPECT_EQ(encodeName(""), "%");
  table.set(s, "render.color_array", table.parse("render.color_array", "%"));
  EXPECT_EQ(s.render.colorArray, "");
  for (const std::string& bad : std::vector<std::string>{" lead", "trail ", "a=b", "x\ny", "\"q\"",
                                                         "50%", std::string(65, 'a')})
    EXPECT_THROW(table.set(s, "render.color_array", AttributeValue(bad)), Error) << bad;
  for (const char* bad : {"50%", "a%2", "%21", "%%"})
    EXPECT_THROW(table.parse("render.color_array", bad), Error) << bad;
  EXPECT_THROW(table.set(s, "render.color_array", 3), Error);
  EXPECT_EQ(s.render.colorArray, "");
}

// A session log keeps a name with spaces, and the empty name, as one word.
TEST(AttributeTableNames, ASessionLogReplaysNamesWithSpaces) {
  const std::vector<ScheduledChange> changes = {
      {3, StateChange::set("render.color_array", std::string("Pressure (Pa)"))},
      {5, StateChange::set("render.color_array", std::string())}};
  std::string text;
  for (const ScheduledChange& c : changes)
    text += concat(c.frame, " ", formatChange(c.change), "\n");
  EXPECT_NE(text.find("3 set render.color_array Pressure%20(Pa)"), std::string::npos) << text;
  const std::vector<ScheduledChange> back = parseSessionLog(text, "test.session");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(std::get<std::string>(back[0].change.value), "Pressure (Pa)");
  EXPECT_EQ(std::get<std::string>(back[1].change.value), "");
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

// A rank that only receives packets mirrors the main context's state and field.
TEST(StateMirror, EqualsTheMainContextsStateAfterTheSamePackets) {
  const auto field = withArrays();
  ParticleState initial;
  initial.render.colorMap = ColorMapName::Plasma;
  MainContext main(initial, FieldUpdate{.field = field}, {});
  StateMirror mirror(main.initialState());
  const AttributeTable& table = AttributeTable::instance();
  for (int f = 0; f < 6; ++f) {
    if (f == 1) main.set("render.color_by", std::string("array"));
    if (f == 3) main.set("render.legend", true);
    if (f == 4) main.set("render.color_array", std::string("pressure"));
    mirror.apply(std::make_shared<const FramePacket>(main.next()));
    EXPECT_EQ(table.describe(mirror.state()), table.describe(main.state())) << "frame " << f;
    ASSERT_TRUE(mirror.field());
    EXPECT_EQ(mirror.field()->colorArray, main.field()->colorArray) << "frame " << f;
    ASSERT_TRUE(mirror.last());
    EXPECT_EQ(mirror.last()->frame, std::uint32_t(f));
  }
  EXPECT_EQ(stateColorScale(mirror.state(), mirror.field().get()).arrayName, "pressure");
}

}  // namespace
}  // namespace sandstorm
