// A curvilinear grid resampled onto its bounding box: the points outside the
// file's cells are marked invalid (analytically: the grid is a sheared box),
// the points inside carry the file's linear field exactly, the count is
// reported, and a converted .vti keeps the mask as vtkValidPointMask.
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLStructuredGridWriter.h>

#include "core/io/field_loader.h"
#include "core/io/field_writer.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

constexpr int kN = 9;           // points per axis
constexpr double kShear = 0.5;  // x moves 0.5 per unit of z

// x = i + 0.5 k, y = j, z = k: a box sheared along x by z.
std::filesystem::path shearedGrid(const std::filesystem::path& dir) {
  vtkNew<vtkStructuredGrid> grid;
  grid->SetDimensions(kN, kN, kN);
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  for (int k = 0; k < kN; ++k)
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) {
        const glm::dvec3 p(i + kShear * k, j, k);
        points->InsertNextPoint(p.x, p.y, p.z);
        const glm::dvec3 a = test::asymmetric(p);
        v->InsertNextTuple3(a.x, a.y, a.z);
      }
  grid->SetPoints(points);
  grid->GetPointData()->SetVectors(v);
  const auto path = dir / "sheared.vts";
  vtkNew<vtkXMLStructuredGridWriter> w;
  w->SetInputData(grid);
  w->SetFileName(path.c_str());
  w->Write();
  return path;
}

// How far inside the sheared box a point is (negative: outside).
double inside(const glm::vec3& p) {
  const double u = p.x - kShear * p.z;
  return std::min(
      {u, (kN - 1) - u, double(p.y), (kN - 1) - double(p.y), double(p.z), (kN - 1) - double(p.z)});
}

TEST(ValidityMask, PointsOutsideTheFilesCellsAreMarkedAndCounted) {
  const auto dir = test::scratch();
  const auto path = shearedGrid(dir);
  LoadOptions options;
  options.resolution = {25, 9, 9};
  LoadReport report;
  const VectorField f = loadField(path, options, &report);
  ASSERT_TRUE(f.hasValidity());
  EXPECT_EQ(report.outside, f.invalidCount());
  std::size_t outside = 0, checked = 0;
  for (int k = 0; k < f.dims().z; ++k)
    for (int j = 0; j < f.dims().y; ++j)
      for (int i = 0; i < f.dims().x; ++i) {
        const glm::vec3 p = f.pointPosition(i, j, k);
        const double d = inside(p);
        if (std::abs(d) < 1e-3) continue;  // on the boundary: either way
        ++checked;
        EXPECT_EQ(f.valid(i, j, k), d > 0.0) << "at " << p.x << " " << p.y << " " << p.z;
        if (d < 0.0) ++outside;
        if (d > 0.0) {
          const glm::vec3 expected(test::asymmetric(glm::dvec3(p)));
          EXPECT_LT(glm::length(f.at(i, j, k) - expected), 1e-4f);
        }
      }
  EXPECT_GT(outside, 100u);
  EXPECT_GT(checked, 1000u);
  EXPECT_NE(std::find(report.notes.begin(), report.notes.end(),
                      concat(report.outside, " of ", f.pointCount(),
                             " points lie outside the file's cells: marked outside the field "
                             "(particles there follow sim.boundary)")),
            report.notes.end());

  // Converted, the mask goes with it, as VTK marks such points.
  const auto vti = dir / "converted.vti";
  saveField(vti, f);
  EXPECT_NE(test::readAll(vti).find("vtkValidPointMask"), std::string::npos);
  LoadReport again;
  const VectorField g = loadField(vti, {}, &again);
  ASSERT_TRUE(g.hasValidity());
  EXPECT_TRUE(std::equal(f.validity().begin(), f.validity().end(), g.validity().begin(),
                         g.validity().end()));
  EXPECT_EQ(again.outside, report.outside);
}

}  // namespace
}  // namespace sandstorm
