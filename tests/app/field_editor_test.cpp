// The field editor's live side: a primitive set in the attribute table
// reaches the walls as the composed field in the next packet, emptying the
// slots gives the field back, a field loaded meanwhile becomes the base; and
// through the application, the saved block loads back to the same particles
// and the baked file holds the composed grid.
#include "app/field_editor.h"

#include <fstream>

#include <gtest/gtest.h>

#include "core/config/app_config.h"
#include "core/editor/field_composer.h"
#include "core/field/analytic_field_factory.h"
#include "core/io/field_loader.h"
#include "core/util/half_float.h"
#include "tests/app/run_process.h"

namespace sandstorm {
namespace {

std::shared_ptr<const VectorField> wind(glm::vec3 v) {
  return std::make_shared<const VectorField>(Box{{-2, -2, 0}, {2, 2, 2}}, glm::ivec3(9, 9, 5),
                                             std::vector<glm::vec3>(9 * 9 * 5, v));
}

// field.precision = "half": the field with its primitives is halves again
// (the walls keep 16-bit grids, and the CPU twin samples what they hold),
// each component the half nearest the composed float.
TEST(FieldEditorDriver, AHalfPrecisionFieldStaysHalvesWithItsPrimitives) {
  MainContext::Options options;
  options.fixedDt = 0.05f;
  auto half = std::make_shared<VectorField>(*wind({1.1f, 0.3f, 0.0f}));
  half->roundToHalf();
  const std::shared_ptr<const VectorField> start = half;
  MainContext main(ParticleState{}, FieldUpdate{.field = start}, options);
  FieldEditor editor(FieldSpec{});
  editor.update(main);
  main.next();
  main.set("primitive.0.kind", std::string("vortex"));
  main.set("primitive.0.position", glm::vec3(0.3f, 0.1f, 1.0f));
  main.next();
  editor.update(main);
  const FramePacket p = main.next();
  ASSERT_TRUE(p.fieldUpdate);
  const VectorField& edited = *p.fieldUpdate->field;
  EXPECT_TRUE(edited.halfPrecision());
  const VectorField composed = composeField(*start, FieldPlacement{}, main.state().primitives);
  int changed = 0;
  for (std::size_t i = 0; i < composed.pointCount(); ++i)
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(edited.values()[i][c], nearestHalf(composed.values()[i][c])) << i;
      changed += composed.values()[i][c] != start->values()[i][c];
    }
  EXPECT_GT(changed, 100);  // the vortex turns the flow
}

TEST(FieldEditorDriver, APrimitiveReachesTheWallsInTheNextPacketAndLeavesNoTrace) {
  MainContext::Options options;
  options.fixedDt = 0.05f;
  const auto start = wind({1.0f, 0.0f, 0.0f});
  FieldPlacement placement;
  placement.offset = {0.5f, 0.0f, 0.0f};
  MainContext main(ParticleState{}, FieldUpdate{.field = start, .placement = placement}, options);
  FieldEditor editor(FieldSpec{});
  editor.update(main);
  EXPECT_EQ(main.next().fieldUpdate->field, start);  // packet 0 brings the field
  editor.update(main);
  EXPECT_FALSE(main.next().fieldUpdate);  // nothing to add: the field stays
  main.set("primitive.3.kind", std::string("source"));
  main.set("primitive.3.position", glm::vec3(0.5f, 0.0f, 1.0f));
  FramePacket p = main.next();  // the change takes effect in this packet
  editor.update(main);
  EXPECT_FALSE(p.fieldUpdate);
  p = main.next();  // and the composed grid travels in the next
  ASSERT_TRUE(p.fieldUpdate);
  const std::vector<FieldPrimitive> slots = main.state().primitives;
  const VectorField expected = composeField(*start, placement, slots);
  EXPECT_TRUE(std::equal(expected.values().begin(), expected.values().end(),
                         p.fieldUpdate->field->values().begin()));
  EXPECT_NE(p.fieldUpdate->field->at(8, 4, 2), start->at(8, 4, 2));  // the source pushes
  EXPECT_EQ(p.fieldUpdate->placement.offset, placement.offset);
  // Unchanged primitives: no new grid.
  editor.update(main);
  EXPECT_FALSE(main.next().fieldUpdate);
  // Disabled: the field it started from, itself.
  main.set("primitive.3.enabled", false);
  main.next();
  editor.update(main);
  p = main.next();
  ASSERT_TRUE(p.fieldUpdate);
  EXPECT_EQ(p.fieldUpdate->field, start);
  // A field loaded while a primitive is on becomes the base.
  main.set("primitive.3.enabled", true);
  main.next();
  editor.update(main);
  const auto loaded = wind({0.0f, 0.0f, -1.0f});
  main.setField(FieldUpdate{.field = loaded});
  main.next();
  editor.update(main);
  p = main.next();
  ASSERT_TRUE(p.fieldUpdate);
  const VectorField onLoaded = composeField(*loaded, FieldPlacement{}, main.state().primitives);
  EXPECT_TRUE(std::equal(onLoaded.values().begin(), onLoaded.values().end(),
                         p.fieldUpdate->field->values().begin()));
  main.set("primitive.3.kind", std::string("none"));
  main.next();
  editor.update(main);
  EXPECT_EQ(main.field()->field, loaded);
  // While the live flow runs the editor waits (the flow makes the field); after, it applies.
  main.set("solver.enabled", true);
  main.set("primitive.0.kind", std::string("wind"));
  main.next();
  editor.update(main);
  EXPECT_EQ(main.field()->field, loaded);
  main.set("solver.enabled", false);
  main.next();
  editor.update(main);
  EXPECT_NE(main.field()->field, loaded);
}

// sandstorm --save-field: the block, included by another configuration, gives
// the same particles frame by frame as the run that composed it; --bake-field
// writes that run's composed grid, which reads back as the same numbers.
TEST(FieldEditorDriver, TheSavedBlockLoadsBackToTheSameParticlesAndTheBakedFileToTheSameGrid) {
  const auto dir = test::scratchDir("field-editor");
  const std::string sets =
      " --set primitive.0.kind=vortex --set primitive.0.position=1,-1,2 --set "
      "primitive.0.strength=4 --set primitive.0.radius=0.7 --set primitive.5.kind=wind --set "
      "primitive.5.axis=0.3,1,0 --set primitive.5.strength=1.5";
  const auto composed = test::runSandstorm(
      "--config tests/data/identity.toml --walls front --frames 40" + sets + " --save-field " +
      (dir / "saved.toml").string() + " --bake-field " + (dir / "baked.vti").string() +
      " --hash-log " + (dir / "composed.txt").string());
  ASSERT_EQ(composed.exitCode, 0) << composed.output;
  {
    std::ofstream back(dir / "back.toml");
    back << "include = \"" SANDSTORM_SOURCE_DIR "/tests/data/identity.toml\"\n";
    std::ifstream saved(dir / "saved.toml");
    back << saved.rdbuf();
  }
  const auto loaded =
      test::runSandstorm("--config " + (dir / "back.toml").string() +
                         " --walls front --frames 40 --hash-log " + (dir / "loaded.txt").string());
  const auto plain = test::runSandstorm(
      "--config tests/data/identity.toml --walls front --frames "
      "40 --hash-log " +
      (dir / "plain.txt").string());
  ASSERT_EQ(loaded.exitCode, 0) << loaded.output;
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  EXPECT_EQ(test::readLines(dir / "loaded.txt"), test::readLines(dir / "composed.txt"));
  EXPECT_NE(test::readLines(dir / "plain.txt"), test::readLines(dir / "composed.txt"));

  // The baked grid: the scene's tornado plus the two primitives, as composeField makes it.
  const AppConfig back = loadConfig(dir / "back.toml");
  EXPECT_EQ(back.particles.primitives[0].kind, PrimitiveKind::Vortex);
  EXPECT_EQ(back.particles.primitives[5].kind, PrimitiveKind::Wind);
  const auto tornado = makeAnalyticField(
      back.field.name, FieldParams(back.field.params.begin(), back.field.params.end()));
  const VectorField expected = composeField(bake(*tornado, back.field.bounds, back.field.dims),
                                            back.field.placement, back.particles.primitives);
  const VectorField baked = loadField(dir / "baked.vti");
  ASSERT_EQ(baked.dims(), expected.dims());
  EXPECT_TRUE(
      std::equal(expected.values().begin(), expected.values().end(), baked.values().begin()));
}

TEST(FieldEditorDriver, BadOutputNamesStopTheStart) {
  const auto r = test::runSandstorm(
      "--config tests/data/identity.toml --walls front --frames 2 --bake-field /tmp/x.png");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("--bake-field /tmp/x.png: expected a .vti or .vdb"), std::string::npos)
      << r.output;
  const auto s = test::runSandstorm(
      "--config tests/data/identity.toml --walls front --frames 2 --save-field "
      "/nonexistent-folder/f.toml");
  EXPECT_NE(s.exitCode, 0);
  EXPECT_NE(s.output.find("--save-field"), std::string::npos) << s.output;
}

}  // namespace
}  // namespace sandstorm
