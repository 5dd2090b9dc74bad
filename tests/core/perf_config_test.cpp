// The performance switches in a configuration: the backend, the field mode,
// the splat renderer and the level of detail.
#include <gtest/gtest.h>

#include "core/config/app_config.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

const char* kWall = R"(
[[wall]]
name = "front"
lower_left = [-1.5, 1.5, 0.0]
lower_right = [1.5, 1.5, 0.0]
upper_left = [-1.5, 1.5, 2.5]
)";

TEST(PerfConfig, DefaultsAreComputeTextureBillboardsWithoutLod) {
  const AppConfig c = parseConfig(kWall, "defaults.toml");
  EXPECT_EQ(c.run.backend, "compute");
  EXPECT_EQ(c.particles.field.mode, FieldMode::Texture);
  EXPECT_EQ(c.particles.render.mode, RenderMode::Billboards);
  EXPECT_FALSE(c.particles.sim.lod);
}

TEST(PerfConfig, EverySwitchIsReadFromItsSection) {
  const std::string text = std::string(R"(
[run]
backend = "tf-gs"
[field]
mode = "equation"
[render]
mode = "auto"
splat_pixels = 3.0
[sim]
lod = true
lod_coverage = 0.3
lod_budget_ms = 16.7
lod_min_scale = 0.2
)") + kWall;
  const AppConfig c = parseConfig(text, "perf.toml");
  EXPECT_EQ(c.run.backend, "tf-gs");
  EXPECT_EQ(c.particles.field.mode, FieldMode::Equation);
  EXPECT_EQ(c.particles.render.mode, RenderMode::Auto);
  EXPECT_FLOAT_EQ(c.particles.render.splatPixels, 3.0f);
  EXPECT_TRUE(c.particles.sim.lod);
  EXPECT_FLOAT_EQ(c.particles.sim.lodCoverage, 0.3f);
  EXPECT_FLOAT_EQ(c.particles.sim.lodBudgetMs, 16.7f);
  EXPECT_FLOAT_EQ(c.particles.sim.lodMinScale, 0.2f);
}

TEST(PerfConfig, AnUnknownFieldModeNamesTheFileAndTheChoices) {
  try {
    parseConfig(std::string("[field]\nmode = \"voxels\"\n") + kWall, "bad.toml");
    FAIL() << "accepted field.mode = voxels";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad.toml"), std::string::npos) << what;
    EXPECT_NE(what.find("equation"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace sandstorm
