// The colour-by quantity in exported polylines (--dump-streamlines,
// --dump-trails): against the analytic values of the fields they sample,
// read back through VTK's own XML reader.
#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include "core/color/color_grid.h"
#include "core/field/analytic_field.h"
#include "core/flow/polyline_color.h"
#include "core/flow/streamline_vtp.h"
#include "core/util/error.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

struct Spin final : AnalyticField {  // solid-body rotation about z at 0.5 rad/s: |curl| = 1 /s
  glm::vec3 evaluate(const glm::vec3& p) const override { return {-0.5f * p.y, 0.5f * p.x, 0.0f}; }
};

// Spin on [-2, 2]^2 x [0, 2], with "heat" = 3x + z + 1 (linear: trilinear
// interpolation is exact), placed 10 m along x at twice its size.
FieldUpdate placedSpin() {
  auto field = std::make_shared<VectorField>(bake(Spin(), Box{{-2, -2, 0}, {2, 2, 2}}, {9, 9, 5}));
  std::vector<float> heat;
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 9; ++j)
      for (int i = 0; i < 9; ++i)
        heat.push_back(3.0f * (-2.0f + 0.5f * float(i)) + 0.5f * float(k) + 1.0f);
  field->addScalars("heat", std::move(heat));
  FieldUpdate u;
  u.field = field;
  u.placement.offset = {10.0f, 0.0f, 0.0f};
  u.placement.scale = 2.0f;
  return u;
}

vtkPolyData* readBack(vtkXMLPolyDataReader* reader, const std::filesystem::path& path) {
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

TEST(PolylineColor, StreamlinesCarryTheVorticityOrTheArrayWhereEachPointIs) {
  FieldUpdate u = placedSpin();
  // Two lines in room coordinates, inside the placed field.
  std::vector<Streamline> lines(2);
  for (int i = 0; i < 5; ++i)
    lines[0].points.push_back({{9.0f + 0.5f * i, 1.0f, 1.0f}, {}});
  for (int i = 0; i < 3; ++i)
    lines[1].points.push_back({{11.0f, -1.0f + i, 3.0f}, {}});

  u.colorGrid = makeColorGrid(*u.field, "");
  const LineColoring vorticity{ColorQuantity::Vorticity, &u, 0.0f, -3.0f};
  const auto v = streamlineColorArray(lines, vorticity);
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->name, "vorticity");
  ASSERT_EQ(v->values.size(), 8u);
  for (float x : v->values)
    EXPECT_NEAR(x, 3.0f, 1e-4f);  // |strength| * 1 /s

  u.colorGrid = makeColorGrid(*u.field, "heat");
  u.colorArray = "heat";
  const LineColoring heat{ColorQuantity::Array, &u, 0.0f, -3.0f};
  const auto h = streamlineColorArray(lines, heat);
  ASSERT_TRUE(h.has_value());
  EXPECT_EQ(h->name, "heat");
  const auto path = test::scratch() / "lines.vtp";
  writeStreamlinesVtp(lines, ColorQuantity::Array, path, "--dump-streamlines",
                      std::span<const PointArray>(&*h, 1));
  vtkNew<vtkXMLPolyDataReader> reader;
  vtkPolyData* read = readBack(reader, path);
  vtkDataArray* values = read->GetPointData()->GetArray("heat");
  ASSERT_NE(values, nullptr);
  ASSERT_EQ(values->GetNumberOfTuples(), 8);
  vtkIdType id = 0;
  for (const Streamline& l : lines)
    for (const StreamlinePoint& p : l.points) {
      const glm::vec3 local = (p.position - glm::vec3(10, 0, 0)) / 2.0f;
      EXPECT_NEAR(values->GetTuple1(id++), 3.0f * local.x + local.z + 1.0f, 1e-4f);
    }

  // Speed and the components are the writer's own arrays; without a grid, nothing.
  EXPECT_FALSE(streamlineColorArray(lines, {ColorQuantity::Speed, &u}).has_value());
  EXPECT_FALSE(streamlineColorArray(lines, {ColorQuantity::Age, &u}).has_value());
  u.colorGrid = nullptr;
  EXPECT_FALSE(streamlineColorArray(lines, heat).has_value());
}

TEST(PolylineColor, TrailsCarryTheirParticlesValueAlongThem) {
  FieldUpdate u = placedSpin();
  u.colorGrid = makeColorGrid(*u.field, "heat");
  u.colorArray = "heat";
  std::vector<Particle> particles(3);
  // A quarter, a half and all of 4 s lived; the positions where heat is 1 + 3 * 0.5 ...
  for (int i = 0; i < 3; ++i) {
    particles[std::size_t(i)].positionLife =
        glm::vec4(10.0f + float(i), 0.0f, 0.0f, 3.0f - float(i));
    particles[std::size_t(i)].velocityKind = glm::vec4(0.0f, 0.0f, 0.0f, 4.0f);
  }
  std::vector<Streamline> trails(2);
  trails[0].points.resize(4);
  trails[1].points.resize(2);
  const std::vector<std::size_t> owners{2, 0};

  const auto age = trailColorArray(trails, owners, particles, {ColorQuantity::Age, &u});
  ASSERT_TRUE(age.has_value());
  EXPECT_EQ(age->name, "age");
  EXPECT_EQ(age->values, (std::vector<float>{0.75f, 0.75f, 0.75f, 0.75f, 0.25f, 0.25f}));

  const auto heat = trailColorArray(trails, owners, particles, {ColorQuantity::Array, &u});
  ASSERT_TRUE(heat.has_value());
  ASSERT_EQ(heat->values.size(), 6u);
  EXPECT_NEAR(heat->values[0], 3.0f * 1.0f + 1.0f, 1e-4f);  // particle 2 at local x = 1
  EXPECT_NEAR(heat->values[5], 1.0f, 1e-4f);                // particle 0 at local x = 0
}

TEST(PolylineColor, AnArrayOfTheWrongLengthIsRefusedAndNamesAreEscaped) {
  std::vector<Streamline> lines(1);
  lines[0].points.resize(3);
  const auto path = test::scratch() / "bad.vtp";
  const PointArray shortArray{"heat", {1.0f, 2.0f}};
  test::expectError(
      [&] {
        writeStreamlinesVtp(lines, ColorQuantity::Speed, path, "--dump-trails",
                            std::span<const PointArray>(&shortArray, 1));
      },
      {"--dump-trails", path.string(), "'heat' has 2 values for 3 points"});
  const PointArray odd{"T<\"a&b\">", {1.0f, 2.0f, 3.0f}};
  writeStreamlinesVtp(lines, ColorQuantity::Speed, path, "--dump-trails",
                      std::span<const PointArray>(&odd, 1));
  vtkNew<vtkXMLPolyDataReader> reader;
  vtkPolyData* read = readBack(reader, path);
  vtkDataArray* values = read->GetPointData()->GetArray("T<\"a&b\">");
  ASSERT_NE(values, nullptr);
  EXPECT_EQ(values->GetTuple1(2), 3.0);
}

}  // namespace
}  // namespace sandstorm
