// `sandstorm FILE`: the seeding plane worked out by hand, and the command line
// on a file of our own with two vector arrays.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "app/file_scene.h"
#include "core/config/byte_size.h"
#include "core/field/analytic_field.h"
#include "core/io/vti_writer.h"
#include "core/sim/attribute_table.h"
#include "tests/app/run_process.h"
#include "tests/io/index_files.h"
#include "tests/io/openfoam_case.h"

namespace sandstorm {
namespace {

struct Uniform final : AnalyticField {
  glm::vec3 v;
  explicit Uniform(glm::vec3 value) : v(value) {}
  glm::vec3 evaluate(const glm::vec3&) const override { return v; }
};

struct Spin final : AnalyticField {  // solid-body rotation about z: no mean flow
  glm::vec3 evaluate(const glm::vec3& p) const override { return {-p.y, p.x, 0.0f}; }
};

TEST(FileScene, AStreamIsSeededJustInsideItsUpstreamFace) {
  // 2 m/s towards -x through a box 10 m long: the plane sits at the +x face,
  // particles live the 5 s it takes to cross, 1000 of them alive at once.
  const VectorField f = bake(Uniform({-2.0f, 0.0f, 0.0f}), Box{{0, -1, 0}, {10, 3, 2}}, {3, 3, 3});
  const Emitter e = seedingPlane(f, 1000);
  EXPECT_EQ(e.shape, EmitterShape::Box);
  EXPECT_NEAR(e.position.x, 9.8f, 1e-4f);
  EXPECT_NEAR(e.position.y, 1.0f, 1e-5f);
  EXPECT_NEAR(e.width, 0.1f, 1e-5f);  // thin along the flow
  EXPECT_NEAR(e.depth, 0.98f * 4.0f, 1e-5f);
  EXPECT_NEAR(e.height, 0.98f * 2.0f, 1e-5f);
  EXPECT_NEAR(e.lifetime, 5.0f, 1e-4f);
  EXPECT_NEAR(e.rate, 200.0f, 1e-2f);
}

TEST(FileScene, AFieldWithoutMeanFlowIsSeededOnItsMiddlePlane) {
  const VectorField f = bake(Spin(), Box{{-2, -2, 0}, {2, 2, 4}}, {5, 5, 5});
  const Emitter e = seedingPlane(f, 1000);
  EXPECT_NEAR(e.position.z, 2.0f, 1e-5f);
  EXPECT_NEAR(e.height, 0.04f, 1e-5f);
  EXPECT_NEAR(e.width, 0.98f * 4.0f, 1e-5f);
}

// Two vector arrays, neither marked active: VTK XML image data, ascii.
std::filesystem::path twoArrays(const std::filesystem::path& dir) {
  const auto path = dir / "two.vti";
  std::ofstream out(path);
  out << R"(<?xml version="1.0"?>
<VTKFile type="ImageData" version="1.0" byte_order="LittleEndian">
<ImageData WholeExtent="0 2 0 2 0 2" Origin="0 0 0" Spacing="1 1 1">
<Piece Extent="0 2 0 2 0 2">
<PointData>
<DataArray type="Float32" Name="wind" NumberOfComponents="3" format="ascii">)";
  for (int i = 0; i < 27; ++i)
    out << "1 0 0 ";
  out << R"(</DataArray>
<DataArray type="Float32" Name="gust" NumberOfComponents="3" format="ascii">)";
  for (int i = 0; i < 27; ++i)
    out << "0 0 3 ";
  out << R"(</DataArray>
</PointData>
</Piece>
</ImageData>
</VTKFile>
)";
  return path;
}

// A field 100 m from the origin, 8 x 4 x 2 m in cells of 1 m: the rake lies on
// the bounds' diagonal (ParaView's line seed), steps a fifth of a cell and
// lines as long as the diagonal; the slice and the probe at the centre.
TEST(FileScene, TheRakeTheSliceAndTheProbeArePlacedInTheField) {
  const VectorField f =
      bake(Uniform({1.0f, 0.0f, 0.0f}), Box{{100, 50, 10}, {108, 54, 12}}, {9, 5, 3});
  AppConfig config;
  openFileScene(config, "far.vti", f);
  const ParticleState& s = config.particles;
  EXPECT_EQ(s.streamlines.shape, RakeShape::Line);
  EXPECT_EQ(s.streamlines.from, glm::vec3(100, 50, 10));
  EXPECT_EQ(s.streamlines.to, glm::vec3(108, 54, 12));
  EXPECT_NEAR(s.streamlines.step, 0.2f, 1e-6f);
  EXPECT_NEAR(s.streamlines.length, std::sqrt(84.0f), 1e-4f);
  EXPECT_FALSE(s.streamlines.enabled);
  EXPECT_EQ(s.slice.origin, glm::vec3(104, 52, 11));
  EXPECT_FALSE(s.slice.enabled);
  EXPECT_EQ(s.probe.position, glm::vec3(104, 52, 11));
}

// A field 22 km wide, away from the origin, on a desktop camera: the near
// plane a hundredth of the camera's distance (depth keeps its precision), the
// flat ground reaching past the field, the ribbons and particles sized to it.
TEST(FileScene, AFieldKilometresWideKeepsDepthPrecisionAndItsGround) {
  const VectorField f =
      bake(Uniform({10.0f, 0.0f, 0.0f}), Box{{0, 0, 0}, {22000, 18000, 2500}}, {12, 10, 6});
  AppConfig config;
  config.walls.push_back(WallSpec{.name = "desktop", .camera = CameraSpec{}});
  openFileScene(config, "atmos.vti", f);
  const glm::vec3 eye = config.walls[0].camera->position, target = config.walls[0].camera->target;
  EXPECT_NEAR(config.run.nearPlane, 0.01f * glm::length(eye - target), 1.0f);
  EXPECT_GT(config.run.farPlane / config.run.nearPlane, 100.0f);
  EXPECT_LT(config.run.farPlane / config.run.nearPlane, 1e4f);
  EXPECT_LE(config.scene.terrainBounds.min.x, 0.0f);
  EXPECT_GE(config.scene.terrainBounds.max.x, 22000.0f);
  EXPECT_GE(config.scene.terrainBounds.max.y, 18000.0f);
  const float diagonal = glm::length(glm::vec3(22000, 18000, 2500));
  EXPECT_NEAR(config.particles.streamlines.width, 0.003f * diagonal, 0.01f);
  EXPECT_NEAR(config.particles.render.size, 0.004f * diagonal, 0.01f);
  EXPECT_FLOAT_EQ(config.particles.streamlines.step, 10.0f);  // the attribute's most
}

// A micro-channel a millimetre long, cells of 50 um: particles, steps, the
// probe and the fade at the ground scale down with it.
TEST(FileScene, AFieldAMillimetreLongGetsItsScale) {
  const VectorField f =
      bake(Uniform({1e-3f, 0.0f, 0.0f}), Box{{0, 0, 0}, {1e-3f, 5e-4f, 5e-4f}}, {21, 11, 11});
  AppConfig config;
  openFileScene(config, "micro.vti", f);
  const ParticleState& s = config.particles;
  const float diagonal = glm::length(glm::vec3(1e-3f, 5e-4f, 5e-4f));
  EXPECT_NEAR(s.render.size, 0.004f * diagonal, 1e-9f);
  EXPECT_NEAR(s.render.softness, 0.01f * diagonal, 1e-9f);
  EXPECT_NEAR(s.streamlines.step, 0.2f * 5e-5f, 1e-10f);
  EXPECT_NEAR(s.probe.radius, 0.02f * diagonal, 1e-9f);
  // Each within its attribute's range (as a menu or a session would set it).
  ParticleState copy = s;
  for (const char* key : {"render.size", "render.softness", "streamlines.step", "probe.radius"})
    EXPECT_TRUE(AttributeTable::instance()
                    .set(copy, key, AttributeTable::instance().get(s, key))
                    .warning.empty())
        << key;
}

// A 2D simulation's plane, one point thick: on the ground its particles
// would fade into it (render.softness); the ground goes a tenth of its width
// below. A field with any thickness keeps the ground at its bottom.
TEST(FileScene, AFlatFieldIsDrawnAboveTheGround) {
  const VectorField flat = bake(Spin(), Box{{0, 0, 2}, {15, 10, 2}}, {16, 11, 1});
  AppConfig config;
  openFileScene(config, "flat.vti", flat);
  EXPECT_NEAR(config.scene.groundHeight, 2.0f - 1.5f, 1e-5f);
  EXPECT_GT(2.0f - config.scene.groundHeight, 5.0f * config.particles.render.softness);

  const VectorField thin = bake(Spin(), Box{{0, 0, 2}, {15, 10, 2.5f}}, {16, 11, 2});
  openFileScene(config, "thin.vti", thin);
  EXPECT_FLOAT_EQ(config.scene.groundHeight, 2.0f);

  // In a CAVE the flat field lies 1 m up, below the eyes, a volume's centre 1.5 m.
  AppConfig cave;
  cave.walls.push_back(WallSpec{.name = "front"});
  openFileScene(cave, "flat.vti", flat);
  const auto roomHeight = [&](float z) {
    return cave.navigation.offset.z + cave.navigation.scale * z;
  };
  EXPECT_NEAR(cave.navigation.scale, 2.4f / 15.0f, 1e-6f);
  EXPECT_NEAR(roomHeight(2.0f), 1.0f, 1e-5f);
  EXPECT_LT(roomHeight(cave.scene.groundHeight), roomHeight(2.0f));
  openFileScene(cave, "thin.vti", thin);
  EXPECT_NEAR(roomHeight(2.25f), 1.5f, 1e-5f);
}

// A legacy .vtk of 4^3 points whose first `holes` vectors are NaN.
std::filesystem::path withHoles(const std::filesystem::path& dir, int holes) {
  const auto path = dir / "holes.vtk";
  std::ofstream out(path);
  out << "# vtk DataFile Version 3.0\nholes\nASCII\nDATASET STRUCTURED_POINTS\n"
      << "DIMENSIONS 4 4 4\nORIGIN 0 0 0\nSPACING 1 1 1\nPOINT_DATA 64\nVECTORS wind float\n";
  for (int p = 0; p < 64; ++p)
    out << (p < holes ? "nan nan nan\n" : "1 0.2 0\n");
  return path;
}

// The reader says once how many of which array's vectors it replaced.
TEST(FileScene, NanVectorsAreReportedOnce) {
  const auto dir = test::scratchDir("file-scene-holes");
  const auto run =
      test::runSandstorm(withHoles(dir, 5).string() +
                         " --frames 1 --set sim.maximum=1000 --screenshot " + dir.string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const std::string said = "5 vectors of array 'wind' are NaN or Inf; replaced by zero";
  const std::size_t first = run.output.find(said);
  ASSERT_NE(first, std::string::npos) << run.output;
  std::size_t mentions = 0;
  for (std::size_t at = run.output.find("NaN"); at != std::string::npos;
       at = run.output.find("NaN", at + 1))
    ++mentions;
  EXPECT_EQ(mentions, 1u) << run.output;
}

TEST(FileScene, AFileWithSeveralArraysAsksWhichAndOpensTheOneNamed) {
  const auto dir = test::scratchDir("file-scene");
  const std::string file = twoArrays(dir).string();
  const auto asks = test::runSandstorm(file + " --frames 3");
  EXPECT_EQ(asks.exitCode, 1) << asks.output;
  for (const char* part : {"two.vti", "several vector arrays", "--array", "wind", "gust"})
    EXPECT_NE(asks.output.find(part), std::string::npos) << part << " in:\n" << asks.output;

  const auto wrong = test::runSandstorm(file + " --array breeze --frames 3");
  EXPECT_EQ(wrong.exitCode, 1);
  EXPECT_NE(wrong.output.find("no array named 'breeze'"), std::string::npos) << wrong.output;

  const auto opens = test::runSandstorm(file + " --array gust --frames 3 --screenshot " +
                                        dir.string() + " --set sim.maximum=2000");
  ASSERT_EQ(opens.exitCode, 0) << opens.output;
  EXPECT_NE(opens.output.find("'gust'"), std::string::npos) << opens.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "desktop.png"));
}

// A scientist opens a field from the folder that holds it: the desktop scene
// (config/desktop.toml) is Sandstorm's, found from wherever it starts.
TEST(FileScene, AFileOpensFromItsOwnFolder) {
  const auto dir = test::scratchDir("file-scene-cwd");
  twoArrays(dir);
  const auto run = test::runCommand("cd '" + dir.string() + "' && '" + SANDSTORM_BINARY +
                                    "' two.vti --array wind --frames 2 --screenshot . "
                                    "--set sim.maximum=1000 2>&1");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "desktop.png"));
}

// `field` as a legacy BINARY .vtk of STRUCTURED_POINTS with `frame`'s origin
// and spacing (to the last bit): the grid its .vti holds.
void writeLegacyVtk(const std::filesystem::path& path, const VectorField& field,
                    const VtkImageFrame& frame) {
  std::ofstream out(path, std::ios::binary);
  const glm::ivec3 n = field.dims();
  out << std::setprecision(17) << "# vtk DataFile Version 3.0\nthe .vti's grid\nBINARY\n"
      << "DATASET STRUCTURED_POINTS\nDIMENSIONS " << n.x << " " << n.y << " " << n.z << "\nORIGIN "
      << frame.origin[0] << " " << frame.origin[1] << " " << frame.origin[2] << "\nSPACING "
      << frame.spacing[0] << " " << frame.spacing[1] << " " << frame.spacing[2] << "\nPOINT_DATA "
      << n.x * n.y * n.z << "\nVECTORS velocity float\n";
  for (int k = 0; k < n.z; ++k)
    for (int j = 0; j < n.y; ++j)
      for (int i = 0; i < n.x; ++i)
        for (const float c : {field.at(i, j, k).x, field.at(i, j, k).y, field.at(i, j, k).z}) {
          const auto bits = std::bit_cast<std::uint32_t>(c);  // big-endian, as the format has it
          for (int b = 3; b >= 0; --b)
            out.put(char((bits >> (8 * b)) & 0xffu));
        }
  out << "\n";
}

// The file is read once: the scene is framed from the very field the run
// starts with (a 512^3 file read twice took twice the time to open).
// A .vti, a parallel image file (.pvti), a legacy .vtk and a series (.pvd)
// of the same grid are framed from their (first step's) headers and seeded
// once read (the walls open meanwhile); a multiblock file (.vtm) of the same
// grid is framed after its read, as every file was. All five open the same
// scene: the same particles and state every frame, the same picture, and the
// emitter setting a --set gave stays as given.
TEST(FileScene, AFileFramedFromItsHeaderOpensAsAFileFramedAfterItsRead) {
  const auto dir = test::scratchDir("file-scene-header");
  struct Drift final : AnalyticField {  // a mean flow along y: not the middle plane's seeding
    glm::vec3 evaluate(const glm::vec3& p) const override {
      return {0.2f * std::sin(p.z), 1.5f + 0.1f * p.x, 0.05f * p.y};
    }
  };
  const VectorField drift = bake(Drift(), {{-1.5f, 0.25f, 2.0f}, {0.5f, 3.25f, 3.5f}}, {17, 25, 7});
  writeVti(dir / "drift.vti", drift);
  test::writePvtiFor(dir / "drift.vti", dir / "drift.pvti");
  writeLegacyVtk(dir / "drift.vtk", drift, *readVtkImageFrame(dir / "drift.vti"));
  test::writeVtmFor(dir / "drift.vti", dir / "drift.vtm");
  std::ofstream(dir / "drift.pvd") << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\">"
                                      "<Collection><DataSet timestep=\"0\" file=\"drift.vti\"/>"
                                      "</Collection></VTKFile>\n";
  const auto open = [&](const std::string& file, const std::string& name) {
    std::filesystem::create_directories(dir / name);
    return test::runSandstorm("'" + (dir / file).string() +
                              "' --headless --frames 12 --set sim.maximum=3000 "
                              "--set emitter.0.lifetime=0.75 --log-level debug --hash-log '" +
                              (dir / name / "hashes.txt").string() + "' --screenshot '" +
                              (dir / name).string() + "'");
  };
  const auto bytes = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  // The scene framed before the field was read, or after.
  const auto before = [](const std::string& out, const std::string& a, const std::string& b) {
    const std::size_t i = out.find(a), j = out.find(b);
    return i != std::string::npos && j != std::string::npos && i < j;
  };
  const auto read = open("drift.vtm", "read");
  ASSERT_EQ(read.exitCode, 0) << read.output;
  EXPECT_TRUE(before(read.output, "field: ", "file scene: ")) << read.output;
  const std::vector<std::string> hashes = test::readLines(dir / "read" / "hashes.txt");
  ASSERT_EQ(hashes.size(), 12u);
  const std::string picture = bytes(dir / "read" / "desktop.png");
  EXPECT_FALSE(picture.empty());
  for (const char* file : {"drift.vti", "drift.pvti", "drift.vtk", "drift.pvd"}) {
    SCOPED_TRACE(file);
    const std::string name = std::string("header-") + (file + 6);
    const auto framed = open(file, name);
    ASSERT_EQ(framed.exitCode, 0) << framed.output;
    EXPECT_TRUE(before(framed.output, "file scene: ", "field: ")) << framed.output;
    EXPECT_NE(framed.output.find("seeding"), std::string::npos) << framed.output;
    EXPECT_EQ(test::readLines(dir / name / "hashes.txt"), hashes);
    EXPECT_TRUE(bytes(dir / name / "desktop.png") == picture) << "the pictures differ";
  }
  std::istringstream last(hashes.back());
  std::string frame, wall;
  std::size_t particles = 0;
  last >> frame >> wall >> particles;
  EXPECT_GT(particles, 100u) << hashes.back();
}

TEST(FileScene, TheFileIsReadOnce) {
  const auto dir = test::scratchDir("file-scene-once");
  twoArrays(dir);
  const auto run = test::runCommand("cd '" + dir.string() + "' && '" + SANDSTORM_BINARY +
                                    "' two.vti --array wind --frames 1 --screenshot . "
                                    "--log-level debug --set sim.maximum=1000 2>&1");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  int reads = 0;
  std::istringstream lines(run.output);
  for (std::string line; std::getline(lines, line);)
    reads += line.find("loaded ") != std::string::npos && line.find("two.vti") != std::string::npos;
  EXPECT_EQ(reads, 1) << run.output;
}

// A configuration given with the file keeps its [field] size settings: its
// memory budget holds for the file as for its own source.
TEST(FileScene, TheConfigurationsMemoryBudgetHoldsForTheFile) {
  const auto dir = test::scratchDir("file-scene-budget");
  writeVti(dir / "wind.vti",
           VectorField(Box{{0, 0, 0}, {1, 1, 1}}, glm::ivec3(64),
                       std::vector<glm::vec3>(64 * 64 * 64, glm::vec3(1.0f, 0.0f, 0.0f))),
           "velocity", VtiCompression::None);  // 3 MiB of vectors
  std::ofstream(dir / "small.toml")
      << "include = \"" << SANDSTORM_SOURCE_DIR
      << "/config/desktop.toml\"\n[field]\nmemory_budget = \"1 MiB\"\n";
  const auto r = test::runSandstorm("'" + (dir / "wind.vti").string() + "' --config '" +
                                    (dir / "small.toml").string() + "' --frames 1");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("field.memory_budget"), std::string::npos) << r.output;
  const auto fits =
      test::runSandstorm("'" + (dir / "wind.vti").string() +
                         "' --frames 1 --set sim.maximum=1000 --screenshot '" + dir.string() + "'");
  EXPECT_EQ(fits.exitCode, 0) << fits.output;
}

// The run's --set of [field] keys shape the file's field: a series whose two
// steps in memory pass the budget is refused naming field.resolution, and
// that advice, taken on the command line, opens it on the grid asked for;
// field.watch follows it. A --set of field.source beside the file is refused. (pointAtFile once
// dropped every [field] --set but the size settings, so the advice taken
// failed the same way again.)
TEST(FileScene, TheRunsFieldSettingsShapeTheFile) {
  const auto dir = test::scratchDir("file-scene-sets");
  std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\">\n<Collection>\n";
  for (int k = 0; k < 3; ++k) {
    const std::string name = "step" + std::to_string(k) + ".vti";
    writeVti(dir / name,
             VectorField(Box{{0, 0, 0}, {1, 1, 1}}, glm::ivec3(64),
                         std::vector<glm::vec3>(64 * 64 * 64, glm::vec3(1.0f, 0.1f * k, 0.0f))),
             "velocity", VtiCompression::None);  // 3 MiB of vectors a step
    pvd += "<DataSet timestep=\"" + std::to_string(k) + "\" file=\"" + name + "\"/>\n";
  }
  std::ofstream(dir / "run.pvd") << pvd << "</Collection>\n</VTKFile>\n";
  const std::string run = "'" + (dir / "run.pvd").string() +
                          "' --frames 1 --set sim.maximum=1000 --set 'field.memory_budget=5 MiB'";
  const auto refused = test::runSandstorm(run);
  ASSERT_EQ(refused.exitCode, 1) << refused.output;
  EXPECT_NE(refused.output.find("field.resolution"), std::string::npos) << refused.output;
  const auto coarser = test::runSandstorm(run + " --set 'field.resolution=[24,20,16]' " +
                                          "--screenshot '" + dir.string() + "'");
  ASSERT_EQ(coarser.exitCode, 0) << coarser.output;
  EXPECT_NE(coarser.output.find("24x20x16 over"), std::string::npos) << coarser.output;
  // field.watch is checked against the file, not the configuration's source.
  const auto watched =
      test::runSandstorm(run + " --set 'field.resolution=[24,20,16]' " + "--set field.watch=true");
  ASSERT_EQ(watched.exitCode, 0) << watched.output;
  EXPECT_NE(watched.output.find("(watched;"), std::string::npos) << watched.output;
  const auto twice = test::runSandstorm(run + " --set field.source=" + (dir / "run.pvd").string());
  EXPECT_EQ(twice.exitCode, 1) << twice.output;
  EXPECT_NE(twice.output.find("give one or the other"), std::string::npos) << twice.output;
}

// field.precision = "auto" (the default): a field whose floats would not
// fit the GPU's room for fields (here a GPU of 100 MB, as the hidden
// --debug-gpu-memory makes the driver's answer: room 75 MB, against the 113 MB
// a 192^3 grid takes at 16 bytes a point) opens as halves and says so; on a larger GPU, or with
// field.precision = "float", it stays floats.
TEST(FileScene, AFieldTooLargeForTheGpuAsFloatsOpensAsHalves) {
  const auto dir = test::scratchDir("file-scene-precision");
  const int n = 192;
  writeVti(dir / "wind.vti",
           VectorField(Box{{0, 0, 0}, {1, 1, 1}}, glm::ivec3(n),
                       std::vector<glm::vec3>(std::size_t(n) * n * n, glm::vec3(0.1f, 0.0f, 0.0f))),
           "velocity", VtiCompression::None);
  const std::string file = "'" + (dir / "wind.vti").string() + "' --frames 1 --set sim.maximum=100";
  const std::string chosen = "field.precision = \"auto\": 16-bit floats chosen";
  const auto small = test::runSandstorm(file + " --debug-gpu-memory 100000000");
  EXPECT_EQ(small.exitCode, 0) << small.output;
  EXPECT_NE(small.output.find(chosen), std::string::npos) << small.output;
  // The floats' bytes, as the message gives them.
  EXPECT_NE(small.output.find(formatByteSize(16.0 * n * n * n)), std::string::npos) << small.output;
  const auto large = test::runSandstorm(file + " --debug-gpu-memory 1000000000");
  EXPECT_EQ(large.exitCode, 0) << large.output;
  EXPECT_EQ(large.output.find(chosen), std::string::npos) << large.output;
  std::ofstream(dir / "float.toml") << "include = \"" << SANDSTORM_SOURCE_DIR
                                    << "/config/desktop.toml\"\n[field]\nprecision = \"float\"\n";
  const auto floats = test::runSandstorm(file + " --debug-gpu-memory 100000000 --config '" +
                                         (dir / "float.toml").string() + "'");
  EXPECT_EQ(floats.exitCode, 0) << floats.output;
  EXPECT_EQ(floats.output.find(chosen), std::string::npos) << floats.output;
}

TEST(FileScene, AnAnalyticFieldBakedTooLargeForTheGpuAsFloatsIsBakedAsHalves) {
  const auto dir = test::scratchDir("file-scene-analytic-precision");
  // The desktop scene's tornado baked at 192^3 points: 81 MiB of floats,
  // enough to ask the GPU.
  std::ofstream(dir / "baked.toml") << "include = \"" << SANDSTORM_SOURCE_DIR
                                    << "/config/desktop.toml\"\n[field]\ndims = [192, 192, 192]\n";
  const std::string run =
      "--config '" + (dir / "baked.toml").string() + "' --frames 1 --set sim.maximum=100";
  const std::string chosen = "field.precision = \"auto\": 16-bit floats chosen";
  const auto small = test::runSandstorm(run + " --debug-gpu-memory 100000000");
  EXPECT_EQ(small.exitCode, 0) << small.output;
  EXPECT_NE(small.output.find("analytic 'tornado' baked to 192x192x192: " + chosen),
            std::string::npos)
      << small.output;
  const auto large = test::runSandstorm(run + " --debug-gpu-memory 1000000000");
  EXPECT_EQ(large.exitCode, 0) << large.output;
  EXPECT_EQ(large.output.find(chosen), std::string::npos) << large.output;
}

TEST(FileScene, AFileThatIsNotThereOrNotAFieldIsAClearError) {
  const auto missing = test::runSandstorm("/nonexistent/wind.vti --frames 1");
  EXPECT_NE(missing.exitCode, 0);
  EXPECT_NE(missing.output.find("/nonexistent/wind.vti"), std::string::npos) << missing.output;
  const auto dir = test::scratchDir("file-scene-bad");
  const auto path = dir / "wind.vti";
  std::ofstream(path) << "not a VTK file\n";
  const auto bad = test::runSandstorm(path.string() + " --frames 1");
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.output.find("wind.vti"), std::string::npos) << bad.output;
  // An OpenFOAM case without its controlDict is watched as a folder: say so.
  std::filesystem::create_directories(dir / "case" / "system");
  std::filesystem::create_directories(dir / "case" / "constant");
  const auto foam =
      test::runSandstorm((dir / "case").string() + " --frames 1 --set field.wait_s=0.1");
  EXPECT_EQ(foam.exitCode, 1) << foam.output;
  for (const char* part :
       {"[sandstorm warn]", "no system/controlDict", "no complete step", "field.wait_s"})
    EXPECT_NE(foam.output.find(part), std::string::npos) << part << " in:\n" << foam.output;
}

// A field at rest (a simulation's array of zeros, or the wrong array) opens,
// and says why nothing moves; a field that moves says nothing of the kind.
TEST(FileScene, AFieldAtRestOpensWithAWarningThatNothingMoves) {
  const auto dir = test::scratchDir("file-scene-rest");
  writeVti(dir / "rest.vti", bake(Uniform({0, 0, 0}), Box{{0, 0, 0}, {2, 1, 1}}, {3, 3, 3}));
  writeVti(dir / "wind.vti", bake(Uniform({1, 0, 0}), Box{{0, 0, 0}, {2, 1, 1}}, {3, 3, 3}));
  const std::string args = " --frames 1 --set sim.maximum=1000 --screenshot " + dir.string();
  const auto rest = test::runSandstorm((dir / "rest.vti").string() + args);
  ASSERT_EQ(rest.exitCode, 0) << rest.output;
  for (const char* part : {"[sandstorm warn]", "rest.vti", "velocity is 0 everywhere", "--array"})
    EXPECT_NE(rest.output.find(part), std::string::npos) << part << " in:\n" << rest.output;
  const auto wind = test::runSandstorm((dir / "wind.vti").string() + args);
  ASSERT_EQ(wind.exitCode, 0) << wind.output;
  EXPECT_EQ(wind.output.find("velocity is 0 everywhere"), std::string::npos) << wind.output;
  // The field editor's blank canvas is at rest as asked: no warning.
  const auto canvas = test::runSandstorm("--config " + std::string(SANDSTORM_SOURCE_DIR) +
                                         "/config/field-editor.toml" + args);
  ASSERT_EQ(canvas.exitCode, 0) << canvas.output;
  EXPECT_NE(canvas.output.find("analytic 'still'"), std::string::npos) << canvas.output;
  EXPECT_EQ(canvas.output.find("velocity is 0 everywhere"), std::string::npos) << canvas.output;
}

// An unstructured grid (VTK XML, ascii): hexahedra over a 4 x 2 x 2 m box
// carrying a wind along x; resampled at its cells' size, it opens as any file.
std::filesystem::path hexahedra(const std::filesystem::path& dir) {
  const auto path = dir / "mesh.vtu";
  std::ofstream out(path);
  const int nx = 4, ny = 2, nz = 2;
  auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  const int points = (nx + 1) * (ny + 1) * (nz + 1), cells = nx * ny * nz;
  out << R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian">
<UnstructuredGrid>
<Piece NumberOfPoints=")"
      << points << "\" NumberOfCells=\"" << cells << R"(">
<PointData Vectors="wind">
<DataArray type="Float32" Name="wind" NumberOfComponents="3" format="ascii">)";
  for (int p = 0; p < points; ++p)
    out << "2 0 0.1 ";
  out << R"(</DataArray>
</PointData>
<Points>
<DataArray type="Float32" NumberOfComponents="3" format="ascii">)";
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        out << i << " " << j << " " << k << " ";
  out << R"(</DataArray>
</Points>
<Cells>
<DataArray type="Int32" Name="connectivity" format="ascii">)";
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        out << id(i, j, k) << " " << id(i + 1, j, k) << " " << id(i + 1, j + 1, k) << " "
            << id(i, j + 1, k) << " " << id(i, j, k + 1) << " " << id(i + 1, j, k + 1) << " "
            << id(i + 1, j + 1, k + 1) << " " << id(i, j + 1, k + 1) << " ";
  out << R"(</DataArray>
<DataArray type="Int32" Name="offsets" format="ascii">)";
  for (int c = 1; c <= cells; ++c)
    out << 8 * c << " ";
  out << R"(</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">)";
  for (int c = 0; c < cells; ++c)
    out << "12 ";
  out << R"(</DataArray>
</Cells>
</Piece>
</UnstructuredGrid>
</VTKFile>
)";
  return path;
}

TEST(FileScene, AnUnstructuredMeshAndAnOpenFoamCaseOpenWithTheirPictures) {
  const auto dir = test::scratchDir("file-scene-mesh");
  const auto mesh = hexahedra(dir);
  const auto run = test::runSandstorm(mesh.string() + " --frames 3 --screenshot " + dir.string() +
                                      " --set sim.maximum=2000");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("VTK XML unstructured grid"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("5x3x3"), std::string::npos) << run.output;  // its cells' size
  // How it was resampled, said once.
  const std::size_t said = run.output.find("resampled to 5 x 3 x 3 points");
  ASSERT_NE(said, std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("resampled to", said + 1), std::string::npos) << run.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "desktop.png"));

  // An OpenFOAM case is a folder: 'sandstorm CASE' opens it, its time folders playing.
  test::FoamCase c;
  c.flow = [](const glm::dvec3& p, double t) { return glm::dvec3(1.0 + t, 0.2 * p.x, 0.0); };
  test::writeFoamCase(c, dir / "cavity");
  std::filesystem::remove(dir / "desktop.png");
  const auto foam = test::runSandstorm((dir / "cavity").string() + " --frames 3 --screenshot " +
                                       dir.string() + " --set sim.maximum=2000");
  ASSERT_EQ(foam.exitCode, 0) << foam.output;
  EXPECT_NE(foam.output.find("3 steps over 1 s ('U'), streamed"), std::string::npos) << foam.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "desktop.png"));
}

TEST(FileScene, AnArrayWithoutAFileIsRefused) {
  const auto r = test::runSandstorm("--array wind --frames 1");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.output.find("--array wind"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace sandstorm
