// Configuration loading: every bundled config loads; every kind of bad config
// fails with an error that names the file, the line and the key.
#include "core/config/app_config.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "core/config/config_sets.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

const std::string kWall = R"(
[[wall]]
name = "front"
lower_left = [-1.5, 1.5, 0.0]
lower_right = [1.5, 1.5, 0.0]
upper_left = [-1.5, 1.5, 3.0]
)";

std::string errorOf(const std::string& text, std::optional<int> monitors = std::nullopt) {
  try {
    parseConfig(text, "test.toml", monitors);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

#define EXPECT_ERROR(text, ...)                          \
  do {                                                   \
    const std::string message = errorOf(text);           \
    for (const char* part : {__VA_ARGS__})               \
      EXPECT_NE(message.find(part), std::string::npos)   \
          << "missing '" << part << "' in: " << message; \
  } while (0)

TEST(Config, EveryBundledConfigLoads) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SANDSTORM_SOURCE_DIR "/config")) {
    if (entry.path().extension() != ".toml") continue;
    EXPECT_NO_THROW(loadConfig(entry.path())) << entry.path();
    ++count;
  }
  EXPECT_GE(count, 5);
}

TEST(Config, ReadsWallsCamerasAndAttributes) {
  const AppConfig c = parseConfig(R"(
[sim]
maximum = 5000
integrator = "rk4"
[render]
size = 0.2
[[emitter]]
shape = "sphere"
rate = 10
[[emitter]]
position = [1, 2, 3]
)" + kWall + R"(
stereo = "side-by-side"
offscreen = { size = [320, 200] }
[[wall]]
name = "desk"
camera = { position = [5, 5, 5], target = [0, 0, 0] }
window = { size = [640, 480], monitor = 0 }
)",
                                  "test.toml");
  EXPECT_EQ(c.particles.sim.maximum, 5000);
  EXPECT_EQ(c.particles.sim.integrator, Integrator::RK4);
  EXPECT_FLOAT_EQ(c.particles.render.size, 0.2f);
  ASSERT_EQ(c.particles.emitters.size(), 2u);
  EXPECT_EQ(c.particles.emitters[0].shape, EmitterShape::Sphere);
  EXPECT_EQ(c.particles.emitters[1].position, glm::vec3(1, 2, 3));
  ASSERT_EQ(c.walls.size(), 2u);
  EXPECT_EQ(c.walls[0].stereo, StereoMode::SideBySide);
  EXPECT_EQ(c.walls[0].offscreenSize, glm::ivec2(320, 200));
  EXPECT_FALSE(c.walls[0].window);
  EXPECT_TRUE(c.walls[1].camera);
  EXPECT_EQ(c.walls[1].window->size, glm::ivec2(640, 480));
}

TEST(Config, UnknownKeysAreRefused) {
  EXPECT_ERROR("[run]\nsed = 4\n" + kWall, "test.toml:2", "run.sed", "unknown key");
  EXPECT_ERROR("[runn]\n" + kWall, "test.toml:1", "runn", "unknown key (did you mean 'run'?)");
  EXPECT_ERROR(kWall + "colour = 3\n", "test.toml:7", "wall[0].colour", "unknown key");
  EXPECT_ERROR("[sim]\nmaximun = 4\n" + kWall, "test.toml:2", "sim.maximun", "sim.maximum");
}

// A file's vector as three one-component arrays: field.name = ["u", "v", "w"].
TEST(Config, AFieldsComponentsAreNamedAsThreeArraysOrTwo) {
  const AppConfig c = parseConfig(
      "[field]\nsource = \"flow.nc\"\nname = [\"u\", \"v\", \"w\"]\n" + kWall, "test.toml");
  EXPECT_EQ(c.field.name, "u,v,w");
  const AppConfig planar =
      parseConfig("[field]\nsource = \"flow.nc\"\nname = [\"u\", \"v\"]\n" + kWall, "test.toml");
  EXPECT_EQ(planar.field.name, "u,v");  // z 0
  EXPECT_ERROR("[field]\nsource = \"flow.nc\"\nname = [\"u\"]\n" + kWall, "test.toml:3",
               "field.name", "three array names");
  EXPECT_ERROR("[field]\nsource = \"flow.nc\"\nname = [\"u\", 2, \"w\"]\n" + kWall, "field.name",
               "three array names");
}

TEST(Config, ColourSettingsAreReadAndAnEmptyOrNonPositiveLogRangeIsRefused) {
  const AppConfig c = parseConfig(R"([render]
color_by = "velocity_z"
color_map = "cool_warm"
color_range = "fixed"
color_min = -2.0
color_max = 2.0
legend = true
)" + kWall,
                                  "test.toml");
  EXPECT_EQ(c.particles.render.colorBy, ColorQuantity::VelocityZ);
  EXPECT_EQ(c.particles.render.colorMap, ColorMapName::CoolWarm);
  EXPECT_EQ(c.particles.render.colorRange, ColorRange::Fixed);
  EXPECT_FLOAT_EQ(c.particles.render.colorMin, -2.0f);
  EXPECT_TRUE(c.particles.render.legend);
  EXPECT_ERROR("[render]\ncolor_range = \"fixed\"\ncolor_min = 3.0\ncolor_max = 1.0\n" + kWall,
               "test.toml:4", "render.color_max", "expected color_max > color_min", "3 to 1");
  EXPECT_ERROR("[render]\ncolor_range = \"fixed\"\ncolor_log = true\ncolor_min = 0.0\n" + kWall,
               "test.toml:4", "render.color_min", "expected color_min > 0 for a log scale");
  EXPECT_ERROR("[render]\ncolor_map = \"jet\"\n" + kWall, "test.toml:2", "render.color_map",
               "viridis");
  // The field's range (the default) is not checked here: the menu's log switch
  // on a range from 0 keeps three decades (ColorScale's note says so).
  EXPECT_NO_THROW(
      parseConfig("[render]\ncolor_by = \"speed\"\ncolor_log = true\n" + kWall, "test.toml"));
}

TEST(Config, AFlowSectionIsReadAndASliceWithoutANormalIsRefused) {
  const AppConfig c = parseConfig(
      "[streamlines]\nenabled = true\nseeds = 4\n[slice]\nenabled = true\nnormal = [1, 0, 0]\n"
      "[probe]\nradius = 0.5\n" +
          kWall,
      "test.toml");
  EXPECT_TRUE(c.particles.streamlines.enabled);
  EXPECT_EQ(c.particles.streamlines.seeds, 4);
  EXPECT_EQ(c.particles.slice.normal, glm::vec3(1, 0, 0));
  EXPECT_FLOAT_EQ(c.particles.probe.radius, 0.5f);
  EXPECT_ERROR("[slice]\nnormal = [0, 0, 0]\n" + kWall, "test.toml:2", "slice.normal",
               "expected a direction");
  EXPECT_ERROR("[streamlines]\nseeds = \"many\"\n" + kWall, "test.toml:2", "streamlines.seeds");
  EXPECT_ERROR("[probe]\nradius = 0.5\nreech = 1\n" + kWall, "test.toml:3", "probe.reech");
}

TEST(Config, MissingCornersAreRefused) {
  EXPECT_ERROR("[[wall]]\nname = \"w\"\nlower_left = [0, 0, 0]\nlower_right = [1, 0, 0]\n",
               "test.toml:1", "wall[0]", "missing required key 'upper_left'");
}

TEST(Config, NonRectangularCornersAreRefused) {
  EXPECT_ERROR(
      "[[wall]]\nlower_left = [0, 0, 0]\nlower_right = [1, 0, 0]\nupper_left = [0.3, 0, 1]\n",
      "test.toml:1", "wall[0]", "not a rectangle");
}

TEST(Config, ZeroSizeWallsAreRefused) {
  EXPECT_ERROR(
      "[[wall]]\nlower_left = [0, 0, 0]\nlower_right = [0, 0, 0]\nupper_left = [0, 0, 1]\n",
      "test.toml:1", "wall[0]", "positive size");
}

TEST(Config, MonitorsThatDoNotExistAreRefused) {
  const std::string text = kWall + "window = { monitor = 3 }\n";
  const std::string message = errorOf(text, 2);
  EXPECT_NE(message.find("test.toml:7"), std::string::npos) << message;
  EXPECT_NE(message.find("wall[0].window.monitor"), std::string::npos) << message;
  EXPECT_NE(message.find("monitor 3 does not exist; 2 connected"), std::string::npos) << message;
}

TEST(Config, UnknownStereoModesAreRefused) {
  EXPECT_ERROR(kWall + "stereo = \"wiggle\"\n", "test.toml:7", "wall[0].stereo",
               "mono, quad-buffer, side-by-side");
}

TEST(Config, BadValuesAreRefusedWithTheirLine) {
  EXPECT_ERROR("[sim]\nmaximum = \"lots\"\n" + kWall, "test.toml:2", "sim.maximum", "integer");
  // An error, so not "clamped": the range, and the key once.
  EXPECT_EQ(errorOf("[render]\nsize = 5000.0\n" + kWall),
            "test.toml:2: render.size: 5000 is outside [1e-07, 1000] m");
  EXPECT_ERROR("[field]\ndims = [0, 4, 4]\n" + kWall, "test.toml:2", "field.dims");
  EXPECT_ERROR(kWall + "lower_left = 3\n", "test.toml",
               "already exists");  // TOML refuses redefinition
  EXPECT_ERROR("[run]\nseed = [1\n", "test.toml", "syntax");
  EXPECT_ERROR("[run]\nseed = 1\n", "test.toml", "no [[wall]]");
  EXPECT_ERROR(kWall + kWall, "test.toml:8", "'front' is used twice");
}

TEST(Config, AMissingTerrainFileIsRefusedWithItsLine) {
  EXPECT_ERROR("[scene]\nterrain = \"no-such-dunes.pgm\"\n" + kWall, "test.toml:2", "scene.terrain",
               "no-such-dunes.pgm", "\"flat\" or a 16-bit PGM");
  EXPECT_ERROR("[scene]\nterrain = \"" SANDSTORM_SOURCE_DIR "/data\"\n" + kWall, "test.toml:2",
               "scene.terrain");  // a folder
  EXPECT_EQ(errorOf("[scene]\nterrain = \"flat\"\n" + kWall), "(no error)");
  EXPECT_EQ(errorOf("[scene]\nterrain = \"" SANDSTORM_SOURCE_DIR "/data/desert.pgm\"\n" + kWall),
            "(no error)");
}

// Includes that loop are named as a loop, at the include that closes it;
// a chain of six includes is refused as too deep, one of five loads.
TEST(Config, IncludesThatLoopOrNestTooDeeplyAreRefused) {
  const auto dir = std::filesystem::temp_directory_path() / "sandstorm-config-includes";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "self.toml") << "include = \"self.toml\"\n";
  std::ofstream(dir / "a.toml") << "include = \"b.toml\"\n";
  std::ofstream(dir / "b.toml") << "# b\ninclude = \"a.toml\"\n";
  for (int i = 1; i <= 6; ++i)
    std::ofstream(dir / ("deep" + std::to_string(i) + ".toml"))
        << "include = \"deep" << i + 1 << ".toml\"\n";
  std::ofstream(dir / "deep7.toml") << kWall;
  const auto errorOfFile = [](const std::filesystem::path& file) -> std::string {
    try {
      loadConfig(file);
    } catch (const Error& e) {
      return e.what();
    }
    return "(no error)";
  };
  const std::string self = errorOfFile(dir / "self.toml");
  EXPECT_NE(self.find("self.toml:1: include: "), std::string::npos) << self;
  EXPECT_NE(self.find("includes loop"), std::string::npos) << self;
  const std::string loop = errorOfFile(dir / "a.toml");
  EXPECT_NE(loop.find("b.toml:2: include: "), std::string::npos) << loop;
  EXPECT_NE(loop.find("a.toml is already being read: includes loop"), std::string::npos) << loop;
  const std::string deep = errorOfFile(dir / "deep1.toml");
  EXPECT_NE(deep.find("deep6.toml:1: include: includes nest more than 5 deep"), std::string::npos)
      << deep;
  EXPECT_EQ(errorOfFile(dir / "deep2.toml"), "(no error)");
}

TEST(Config, TheFieldsMemoryBudgetIsASizeOrAutomatic) {
  const auto budget = [](const std::string& value) {
    return parseConfig("[field]\nmemory_budget = " + value + "\n" + kWall, "test.toml")
        .field.memoryBudget;
  };
  EXPECT_EQ(budget("\"16 GiB\""), std::uint64_t{16} << 30);
  EXPECT_EQ(budget("\"800MiB\""), std::uint64_t{800} << 20);
  EXPECT_EQ(budget("\"2.5 GB\""), std::uint64_t{2500000000});
  EXPECT_EQ(budget("3000000000"), std::uint64_t{3000000000});
  EXPECT_EQ(budget("\"auto\""), 0u);
  // Automatic: half the machine's memory.
  FieldSpec automatic;
  EXPECT_EQ(fieldMemoryBudget(automatic), hostMemoryBytes() / 2);
  automatic.memoryBudget = 12345678;
  EXPECT_EQ(fieldMemoryBudget(automatic), 12345678u);
  for (const char* bad : {"\"lots\"", "\"16 GiBs\"", "\"-4 GiB\"", "100", "\"1 KiB\"", "true"})
    EXPECT_ERROR("[field]\nmemory_budget = " + std::string(bad) + "\n" + kWall, "test.toml:2",
                 "field.memory_budget", "16 GiB");
  EXPECT_EQ(parseConfig("[field]\nread_ahead = 6\n" + kWall, "test.toml").field.readAhead, 6);
  EXPECT_ERROR("[field]\nread_ahead = -1\n" + kWall, "test.toml:2", "field.read_ahead", "0..64");
  EXPECT_TRUE(parseConfig(kWall, "test.toml").field.uploadAhead);
  EXPECT_FALSE(
      parseConfig("[field]\nupload_ahead = false\n" + kWall, "test.toml").field.uploadAhead);
  EXPECT_ERROR("[field]\nupload_ahead = 2\n" + kWall, "test.toml:2", "field.upload_ahead",
               "true or false");
  EXPECT_FALSE(parseConfig(kWall, "test.toml").field.halfPrecision);
  EXPECT_TRUE(
      parseConfig("[field]\nprecision = \"half\"\n" + kWall, "test.toml").field.halfPrecision);
  EXPECT_ERROR("[field]\nprecision = \"double\"\n" + kWall, "test.toml:2", "field.precision",
               "float, half");
  EXPECT_EQ(parseConfig(kWall, "test.toml").field.storage, FieldSpec::Storage::Auto);
  EXPECT_EQ(parseConfig("[field]\nstorage = \"sparse\"\n" + kWall, "test.toml").field.storage,
            FieldSpec::Storage::Sparse);
  EXPECT_EQ(parseConfig("[field]\nstorage = \"dense\"\n" + kWall, "test.toml").field.storage,
            FieldSpec::Storage::Dense);
  EXPECT_ERROR("[field]\nstorage = \"nano\"\n" + kWall, "test.toml:2", "field.storage",
               "auto, dense, sparse");
}

TEST(Config, ReadsAndChecksGpuTuning) {
  const AppConfig c = parseConfig(
      "[gpu]\nsplat = \"atomic\"\nsplat_chunk = 37\nsplat_list = 500\ntrail_pass = \"tiled\"\n"
      "field_storage = \"texture\"\nupdate_items = 8\nscan_spin = 0\nupload_context = false\n" +
          kWall,
      "test.toml");
  EXPECT_EQ(c.gpu.splat, GpuTuning::Splat::Atomic);
  EXPECT_EQ(c.gpu.splatChunk, 37u);
  EXPECT_EQ(c.gpu.splatList, 500u);
  EXPECT_EQ(c.gpu.trailPass, GpuTuning::TrailPass::Tiled);
  EXPECT_EQ(c.gpu.fieldStorage, GpuTuning::FieldStorage::Texture);
  EXPECT_EQ(c.gpu.updateItems, 8);
  EXPECT_EQ(c.gpu.scanSpin, 0u);
  EXPECT_FALSE(c.gpu.uploadContext);
  const AppConfig d = parseConfig(kWall, "test.toml");
  EXPECT_EQ(d.gpu.splat, GpuTuning::Splat::Tiled);
  EXPECT_EQ(d.gpu.updateItems, 4);
  EXPECT_EQ(d.gpu.trailPass, GpuTuning::TrailPass::Auto);
  EXPECT_FALSE(d.gpu.scanSpin.has_value());
  EXPECT_TRUE(d.gpu.uploadContext);
  EXPECT_ERROR("[gpu]\nupload_context = 1\n" + kWall, "test.toml:2", "gpu.upload_context",
               "true or false");
  EXPECT_ERROR("[gpu]\nupdate_items = 3\n" + kWall, "test.toml:2", "gpu.update_items",
               "1, 2, 4 or 8");
  EXPECT_ERROR("[gpu]\nfield_storage = \"ssbo\"\n" + kWall, "test.toml:2", "gpu.field_storage",
               "auto, texture");
  EXPECT_ERROR("[gpu]\nsplat = \"fast\"\n" + kWall, "test.toml:2", "gpu.splat", "tiled, atomic");
  EXPECT_ERROR("[gpu]\ntrail_pass = \"lines\"\n" + kWall, "test.toml:2", "gpu.trail_pass",
               "auto, tiled, atomic");
  EXPECT_ERROR("[gpu]\nsplat_chunk = 0\n" + kWall, "test.toml:2", "gpu.splat_chunk");
  EXPECT_ERROR("[gpu]\nwarp = 32\n" + kWall, "test.toml", "warp");
}

TEST(Config, OffscreenWallsChooseTheirGpu) {
  const std::string wall = kWall + "gpu = 1\noffscreen = { size = [64, 64] }\n";
  const AppConfig c = parseConfig("[run]\ngpus = \"round-robin\"\n" + wall, "test.toml");
  EXPECT_TRUE(c.run.gpusRoundRobin);
  EXPECT_EQ(c.walls[0].gpu, 1);
  EXPECT_FALSE(parseConfig(kWall, "test.toml").walls[0].gpu.has_value());
  EXPECT_ERROR(kWall + "gpu = 64\n", "test.toml:7", "wall[0].gpu", "0..63");
  EXPECT_ERROR(kWall + "gpu = 1\nwindow = { size = [64, 64] }\n", "test.toml:7", "wall[0].gpu",
               "display's GPU");
  EXPECT_ERROR("[run]\ngpus = \"all\"\n" + kWall, "test.toml:2", "run.gpus", "first, round-robin");
}

// The contexts a run opens decide whether llvmpipe rasterizes in the drawing
// threads (contexts/platform/software_rasterizer.h).
TEST(Config, CountsTheContextsARunDrawsWith) {
  int walls = 0;
  const auto wall = [&](const std::string& how) {
    std::string text = kWall + how + "\n";
    return text.replace(text.find("\"front\""), 7, "\"w" + std::to_string(walls++) + "\"");
  };
  const auto contexts = [](const std::string& text) {
    return parseConfig(text, "test.toml").glContexts();
  };
  const std::string offscreen = "offscreen = { size = [64, 64] }";
  const std::string window = "window = { size = [64, 64] }";
  EXPECT_EQ(contexts(wall(offscreen)), 1);
  EXPECT_EQ(contexts(wall(offscreen) + wall(offscreen) + wall(offscreen)), 1);
  const std::string perWall = "[run]\noffscreen_contexts = \"per-wall\"\n";
  EXPECT_EQ(contexts(perWall + wall(offscreen) + wall(offscreen) + wall(offscreen)), 3);
  EXPECT_EQ(contexts(wall(offscreen) + wall(offscreen) + wall("gpu = 1\n" + offscreen)), 2);
  EXPECT_EQ(contexts(wall(window)), 1);
  EXPECT_EQ(contexts(wall(window) + wall(window) + wall(offscreen)), 3);
}

// Pixels are checked as numbers before they become integers (an infinite or
// huge size was undefined behaviour: a fuzz_config find), and a number is finite.
TEST(Config, WindowSizesBeyondTheirRangeOrInfiniteAreRefused) {
  EXPECT_ERROR(kWall + "window = { size = [1280, 71e3020] }\n", "test.toml:7",
               "wall[0].window.size", "expected");
  EXPECT_ERROR(kWall + "window = { size = [1280, inf] }\n", "test.toml:7", "wall[0].window.size",
               "finite");
  EXPECT_ERROR(kWall + "window = { size = [1e20, 720] }\n", "test.toml:7", "wall[0].window.size",
               "16..16384 pixels");
  EXPECT_ERROR(kWall + "window = { position = [-1e12, 0] }\n", "test.toml:7",
               "wall[0].window.position", "-65536..65536");
  EXPECT_ERROR(kWall + "offscreen = { size = [nan, 64] }\n", "test.toml:7",
               "wall[0].offscreen.size", "finite");
  EXPECT_ERROR("[render]\nsize = inf\n" + kWall, "test.toml:2", "render.size", "finite");
  // A double beyond float's range has no float to become.
  EXPECT_ERROR("[render]\nsize = 1e300\n" + kWall, "test.toml:2", "render.size", "3.4e38");
  EXPECT_ERROR("[field]\nbounds_min = [0, -1e39, 0]\n" + kWall, "test.toml:2", "field.bounds_min",
               "3.4e38");
  const AppConfig ok = parseConfig(
      kWall + "window = { size = [640.0, 480], position = [-20, 0] }\n", "test.toml", 2);
  EXPECT_EQ(ok.walls.at(0).window->size, glm::ivec2(640, 480));
  EXPECT_EQ(ok.walls.at(0).window->position, glm::ivec2(-20, 0));
}

// A value judged after it is read (against another key, or a range of its
// own) is named at its own line, not its section's.
TEST(Config, AValueOutsideItsRangeIsNamedAtItsOwnLine) {
  EXPECT_ERROR("[head]\nposition = [0, 0, 1.7]\n\neye_separation = -1\n" + kWall,
               "test.toml:4:", "head.eye_separation", "0..0.5 m");
  EXPECT_ERROR("[run]\nseed = 1\nnear = 5\nfar = 1\n" + kWall, "test.toml:3:", "run.near/far");
  EXPECT_ERROR("[run]\nseed = 1\nfar = -1\n" + kWall, "test.toml:3:", "run.near/far");
  EXPECT_ERROR("[tracking]\nport = 5000\nstale_ms = 0\n" + kWall,
               "test.toml:3:", "tracking.stale_ms");
  EXPECT_ERROR(kWall + "offscreen = { size = [64, 64] }\nstereo = \"quad-buffer\"\n",
               "test.toml:8:", "wall[0].stereo");
  // Where the key is absent, its section's line.
  EXPECT_ERROR("[head]\nmode = \"scripted\"\n" + kWall, "test.toml:1:", "head.path");
}

TEST(Config, IntegersBeyond64BitsAreRefusedNotClamped) {
  const std::string big = "0b1" + std::string(64, '0');  // 2^64
  EXPECT_ERROR("[run]\nseed = " + big + "\n" + kWall, "test.toml:2", "does not fit in 64 bits");
  EXPECT_ERROR("[run]\nseed = 0x1_0000_0000_0000_0000\n" + kWall, "test.toml:2", "64 bits");
  EXPECT_ERROR("[run]\nseed = 0o2000000000000000000000\n" + kWall, "test.toml:2", "64 bits");
  EXPECT_ERROR("[sim]\nmaximum = 9223372036854775808\n" + kWall, "test.toml:2", "64 bits");
  EXPECT_ERROR("[sim]\nmaximum = [1,\n -9223372036854775809]\n" + kWall, "test.toml:3", "64 bits");
  // The extremes themselves fit (and are then judged by the key's own range);
  // digits inside strings and comments are not integers.
  EXPECT_ERROR("[sim]\nmaximum = -9223372036854775808\n" + kWall, "sim.maximum");
  // Beyond an attribute's int, the integer is quoted as written, not as clamped.
  EXPECT_ERROR("[sim]\nmaximum = 99999999999\n" + kWall, "test.toml:2",
               "sim.maximum: 99999999999 is outside [0, 1e+08] particles");
  EXPECT_EQ(
      errorOf("# 99999999999999999999\n[run]\nname = \"0b" + std::string(70, '1') + "\"\n" + kWall)
          .find("64 bits"),
      std::string::npos);
}

TEST(Config, DeeplyNestedValuesAreRefusedBeforeTheParserRecurses) {
  // Thousands of levels would overflow the stack inside toml11.
  const int n = 20000;
  EXPECT_ERROR("[run]\nseed = " + std::string(n, '[') + std::string(n, ']') + "\n" + kWall,
               "test.toml:2", "nested more than 32 deep");
  EXPECT_ERROR("[run]\nname = " + std::string(n, '{') + "\n" + kWall, "test.toml:2", "32 levels");
  // Brackets in strings and comments do not nest; 32 levels still parse.
  EXPECT_EQ(errorOf("# " + std::string(100, '[') + "\n[run]\nname = \"" + std::string(100, '{') +
                    "\"\n" + kWall)
                .find("nested"),
            std::string::npos);
  EXPECT_EQ(errorOf("[run]\nseed = " + std::string(32, '[') + std::string(32, ']') + "\n" + kWall)
                .find("nested"),
            std::string::npos);
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

TEST(Pvx, ParaViewWallsBecomeTheSameCaveAsOurs) {
  const AppConfig pvx = loadConfig(SANDSTORM_SOURCE_DIR "/config/cave4-pvx.toml");
  const AppConfig ours = loadConfig(SANDSTORM_SOURCE_DIR "/config/cave4-desktop.toml");
  ASSERT_EQ(pvx.walls.size(), 4u);
  for (const WallSpec& p : pvx.walls) {
    const auto it = std::find_if(ours.walls.begin(), ours.walls.end(),
                                 [&](const WallSpec& w) { return w.name == p.name; });
    ASSERT_NE(it, ours.walls.end()) << p.name;
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(p.corners.lowerLeft[a], it->corners.lowerLeft[a], 1e-6f) << p.name;
      EXPECT_NEAR(p.corners.lowerRight[a], it->corners.lowerRight[a], 1e-6f) << p.name;
      EXPECT_NEAR(p.corners.upperLeft[a], it->corners.upperLeft[a], 1e-6f) << p.name;
    }
    ASSERT_TRUE(p.window);
    EXPECT_EQ(p.window->size, glm::ivec2(480, 480));
  }
}

TEST(Pvx, BadMachinesAreRefusedByName) {
  const auto errorOf = [](const std::string& text) {
    try {
      parseConfig(text, "p.toml");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  const auto dir = std::filesystem::temp_directory_path();
  std::ofstream(dir / "skew.pvx") << "<pvx>\n<Machine Name=\"w\" LowerLeft=\"0 0 0\" "
                                     "LowerRight=\"1 0 0\" UpperRight=\"1.4 1 0\"/>\n</pvx>";
  std::ofstream(dir / "short.pvx") << "<pvx>\n\n<Machine Name=\"w\" LowerLeft=\"0 0\" "
                                      "LowerRight=\"1 0 0\" UpperRight=\"1 1 0\"/>";
  std::ofstream(dir / "none.pvx") << "<pvx></pvx>";
  EXPECT_NE(
      errorOf("pvx = \"" + (dir / "skew.pvx").string() + "\"").find("skew.pvx:2: machine 'w'"),
      std::string::npos);
  EXPECT_NE(errorOf("pvx = \"" + (dir / "short.pvx").string() + "\"")
                .find("LowerLeft=\"0 0\"; expected three numbers"),
            std::string::npos);
  EXPECT_NE(errorOf("pvx = \"" + (dir / "none.pvx").string() + "\"").find("no <Machine>"),
            std::string::npos);
  EXPECT_NE(errorOf("pvx = \"" + (dir / "none.pvx").string() + "\"\n[[wall]]\nname = \"x\"\n")
                .find("not both"),
            std::string::npos);
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

TEST(Config, FieldPlacementTurnsAsConfigured) {
  const std::string wall =
      "[[wall]]\nlower_left = [0, 0, 0]\nlower_right = [1, 0, 0]\nupper_left = [0, 0, 1]\n";
  // A y-up data set stood up in the z-up room: the field's +y becomes the room's +z.
  const AppConfig up = parseConfig(
      "[field]\nrotation_deg = [90, 0, 0]\noffset = [1, 2, 3]\nscale = 2\n" + wall, "t.toml");
  const glm::vec3 v = up.field.placement.vectorToRoom({0, 1, 0});
  EXPECT_NEAR(v.x, 0.0f, 1e-6f);
  EXPECT_NEAR(v.y, 0.0f, 1e-6f);
  EXPECT_NEAR(v.z, 2.0f, 1e-6f);  // scaled with the placement
  const glm::vec3 p =
      up.field.placement.toRoom({0, 0, 1});  // the field's +z points to the room's -y
  EXPECT_NEAR(p.y, 2.0f - 2.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(up.field.placement.toLocal(p), glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
  // yaw_deg = 90 turns the field's +x to the room's +y.
  const AppConfig yaw = parseConfig("[field]\nyaw_deg = 90\n" + wall, "t.toml");
  const glm::vec3 w = yaw.field.placement.vectorToRoom({1, 0, 0});
  EXPECT_NEAR(w.y, 1.0f, 1e-6f);
  EXPECT_NEAR(w.x, 0.0f, 1e-6f);
  try {
    parseConfig("[field]\nyaw_deg = 90\nrotation_deg = [0, 0, 90]\n" + wall, "t.toml");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not both"), std::string::npos);
  }
}

}  // namespace
}  // namespace sandstorm

namespace sandstorm {
namespace {

TEST(Config, ReadsTracking) {
  const AppConfig c = parseConfig(R"([tracking]
source = "dtrack"
port = 5001
multicast = "239.1.2.3"
sender = ["10.0.0.5", "10.0.0.6"]
interface = "10.0.0.1"
head_body = 3
wand_flystick = 1
offset = [0.0, 1.5, 0.0]
rotation_deg = [90.0, 0.0, 0.0]
stale_ms = 100
eye_offset = [0.0, 0.08, -0.05]
head_right = [0, 0, -2]
head_up = [0, 1, 0]
grab_button = 0

[navigation]
fly_speed = 3.0
turn_speed_deg = 30.0
)" + kWall,
                                  "test.toml");
  EXPECT_EQ(c.tracking.source, TrackingSource::DTrack);
  EXPECT_EQ(c.tracking.port, 5001);
  EXPECT_EQ(c.tracking.multicast, "239.1.2.3");
  EXPECT_EQ(c.tracking.senders, (std::vector<std::string>{"10.0.0.5", "10.0.0.6"}));
  EXPECT_EQ(c.tracking.interfaceAddress, "10.0.0.1");
  EXPECT_EQ(
      parseConfig("[tracking]\nsender = \"192.168.0.20\"\n" + kWall, "test.toml").tracking.senders,
      std::vector<std::string>{"192.168.0.20"});
  EXPECT_EQ(c.tracking.headBody, 3);
  EXPECT_EQ(c.tracking.wandFlystick, 1);
  EXPECT_EQ(c.tracking.offset, glm::vec3(0, 1.5f, 0));
  EXPECT_NEAR((c.tracking.rotation * glm::vec3(0, 1, 0)).z, 1.0f, 1e-6f);  // y up becomes z up
  EXPECT_EQ(c.tracking.staleMs, 100.0f);
  EXPECT_EQ(c.tracking.headRight, glm::vec3(0, 0, -1));  // normalised
  EXPECT_EQ(c.tracking.grabButton, 0);
  EXPECT_EQ(c.navigation.flySpeed, 3.0f);
  EXPECT_EQ(c.navigation.turnSpeedDeg, 30.0f);
}

TEST(Config, MaxFpsPacesARunOrIsRefused) {
  EXPECT_EQ(parseConfig("[run]\nmax_fps = 90\n" + kWall, "test.toml").run.maxFps, 90.0);
  EXPECT_EQ(parseConfig(kWall, "test.toml").run.maxFps, 0.0);
  EXPECT_ERROR("[run]\nmax_fps = -1\n" + kWall, "test.toml:2", "run.max_fps", "0 (no limit)");
  EXPECT_ERROR("[run]\nmax_fps = 5000\n" + kWall, "run.max_fps", "1000");
}

TEST(Config, BadTrackingIsRefusedWithItsLineAndKey) {
  EXPECT_ERROR("[tracking]\nsource = \"vrpn\"\n" + kWall, "test.toml:2", "tracking.source",
               "dtrack");
  EXPECT_ERROR("[tracking]\nport = 70000\n" + kWall, "test.toml:2", "tracking.port", "1..65535");
  EXPECT_ERROR("[tracking]\nmulticast = \"10.0.0.1\"\n" + kWall, "tracking.multicast",
               "multicast group");
  EXPECT_ERROR("[tracking]\nmulticast = \"239.1.2\"\n" + kWall, "tracking.multicast");
  EXPECT_ERROR("[tracking]\nmulticast = \"239.01.2.3\"\n" + kWall, "tracking.multicast");
  EXPECT_ERROR("[tracking]\nsender = \"dtrack.local\"\n" + kWall, "test.toml:2", "tracking.sender",
               "IPv4 address");
  EXPECT_ERROR("[tracking]\nsender = [\"10.0.0.5\", \"10.0.0.256\"]\n" + kWall, "tracking.sender",
               "10.0.0.256");
  EXPECT_ERROR("[tracking]\nsender = []\n" + kWall, "tracking.sender", "a list of addresses");
  EXPECT_ERROR("[tracking]\nsender = [5]\n" + kWall, "tracking.sender");
  EXPECT_ERROR("[tracking]\nsender = \"239.1.2.3\"\n" + kWall, "tracking.sender");
  EXPECT_ERROR("[tracking]\ninterface = \"10.0.0\"\n" + kWall, "test.toml:2", "tracking.interface",
               "local IPv4 address");
  EXPECT_ERROR("[tracking]\nstale_ms = 0\n" + kWall, "tracking.stale_ms");
  EXPECT_ERROR("[tracking]\nhead_right = [0, 0, 0]\n" + kWall, "test.toml:2", "tracking.head_right",
               "non-zero");
  EXPECT_ERROR("[tracking]\nhead_up = [1, 0, 0]\n" + kWall, "tracking.head_right/head_up",
               "perpendicular");
  EXPECT_ERROR("[tracking]\neye_offset = [5, 0, 0]\n" + kWall, "tracking.eye_offset");
  EXPECT_ERROR("[tracking]\ntrigger_button = 40\n" + kWall, "tracking.trigger_button", "0..31");
  EXPECT_ERROR("[tracking]\nsorce = \"dtrack\"\n" + kWall, "test.toml:2", "tracking.sorce",
               "unknown key");
  EXPECT_ERROR("[navigation]\nfly_speed = -1\n" + kWall, "navigation.fly_speed");
  EXPECT_ERROR("[head]\nright = [0, 2, 0]\n" + kWall, "head.right", "unit vector");
  EXPECT_ERROR("[head]\nright = [0, 1, 0]\nyaw_deg = 3\n" + kWall, "not both");
}

TEST(Config, AHeadCanBeGivenByItsEyesAxis) {
  const AppConfig c = parseConfig("[head]\nright = [0.6, 0.8, 0.0]\n" + kWall, "test.toml");
  ASSERT_TRUE(c.head.right);
  EXPECT_EQ(*c.head.right, glm::vec3(0.6f, 0.8f, 0.0f));
}

// --set for configuration settings: read on top of the file, in order, each
// checked as the file's keys are, errors naming the --set; attributes left to
// the attribute table.
TEST(Config, SetsChangeConfigurationSettingsAsAFileReadLastWould) {
  EXPECT_TRUE(isConfigSetting("gpu.update_items"));
  EXPECT_TRUE(isConfigSetting("field.precision"));
  EXPECT_TRUE(isConfigSetting("head.position"));
  EXPECT_FALSE(isConfigSetting("field.mode"));  // an attribute
  EXPECT_FALSE(isConfigSetting("render.size"));
  EXPECT_FALSE(isConfigSetting("emitter.0.rate"));
  EXPECT_FALSE(isConfigSetting("wall.0.name"));  // walls are an array
  EXPECT_FALSE(isConfigSetting("gpu"));

  AppConfig c = parseConfig("[gpu]\nupdate_items = 8\n[run]\nframes = 5\n" + kWall, "test.toml");
  const float size = c.particles.render.size;
  applyConfigSets(c, {"gpu.update_items=1", "gpu.update_items=2", "field.precision=half",
                      "head.position=0.5,0,1.5", "field.source=data/storm.vti", "render.size=0.5",
                      "field.resolution=[8, 8, 8]"});
  EXPECT_EQ(c.gpu.updateItems, 2);  // the last one
  EXPECT_EQ(c.run.frames, 5);       // untouched
  EXPECT_TRUE(c.field.halfPrecision);
  EXPECT_EQ(c.head.position, glm::vec3(0.5f, 0.0f, 1.5f));
  EXPECT_EQ(c.field.source, "data/storm.vti");  // from where the program started
  EXPECT_EQ(c.field.resolution, glm::ivec3(8));
  EXPECT_EQ(c.particles.render.size, size);  // an attribute: applySets' (app/)

  const auto refusal = [&](const std::string& set) {
    AppConfig d = c;
    try {
      applyConfigSets(d, {set});
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(refusal("gpu.update_items=3"),
            "--set gpu.update_items=3: gpu.update_items: expected 1, 2, 4 or 8");
  EXPECT_NE(refusal("field.sourc=x").find("--set field.sourc=x: field.sourc: unknown key"),
            std::string::npos);
  EXPECT_NE(refusal("gpu.upload_context=maybe").find("gpu.upload_context"), std::string::npos);
  EXPECT_NE(refusal("head.position=1,2").find("--set head.position=1,2: head.position"),
            std::string::npos);
  EXPECT_NE(refusal("gpu.update items=2").find("expected a key of letters"), std::string::npos);
}

}  // namespace
}  // namespace sandstorm
