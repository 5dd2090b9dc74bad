// A .pvd whose times have several parts (ParaView's output of a parallel run:
// a file a rank, part="0", part="1", ...): each time opens whole, its parts
// read and resampled together, as one field and as a streamed series' steps,
// equal to the analytic field the parts were written from by VTK's writers.
// Before, only part 0 was read: half the domain shown as if it were all.
#include <gtest/gtest.h>

#include <vtkAppendFilter.h>
#include <vtkDataArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "core/io/field_loader.h"
#include "core/io/pvd_file.h"
#include "core/io/series_index.h"
#include "core/io/series_reader.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

constexpr double kSpacing = 0.25;

// The asymmetric field times `scale` over x in [x0, x0 + 2], y and z in [0, 1].
vtkSmartPointer<vtkImageData> half(int x0, double scale) {
  const int i0 = int(x0 / kSpacing);
  const int extent[6] = {i0, i0 + 8, 0, 4, 0, 4};
  vtkSmartPointer<vtkImageData> image =
      test::asymmetricImage(extent, {0, 0, 0}, glm::dvec3(kSpacing));
  vtkDataArray* v = image->GetPointData()->GetArray("velocity");
  for (vtkIdType i = 0; i < v->GetNumberOfTuples(); ++i) {
    double t[3];
    v->GetTuple(i, t);
    v->SetTuple3(i, scale * t[0], scale * t[1], scale * t[2]);
  }
  return image;
}

// Step n: part 0 an image (.vti), part 1 an unstructured grid (.vtu) of the
// other half, listed part 1 first (the order of parts is theirs, not the file's).
std::filesystem::path writeParts(const std::filesystem::path& dir, int steps) {
  std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\">\n<Collection>\n";
  for (int n = 0; n < steps; ++n) {
    const std::string a = "run_" + std::to_string(n) + "_0.vti";
    const std::string b = "run_" + std::to_string(n) + "_1.vtu";
    test::writeRawVti(half(0, 1.0 + n), dir / a);
    vtkNew<vtkAppendFilter> grid;
    grid->AddInputData(half(2, 1.0 + n));
    grid->Update();
    vtkNew<vtkXMLUnstructuredGridWriter> w;
    w->SetInputData(grid->GetOutput());
    w->SetCompressorTypeToNone();
    w->SetFileName((dir / b).c_str());
    EXPECT_EQ(w->Write(), 1);
    const std::string t = std::to_string(0.5 * n);
    pvd += "<DataSet timestep=\"" + t + "\" group=\"\" part=\"1\" file=\"" + b + "\"/>\n";
    pvd += "<DataSet timestep=\"" + t + "\" group=\"\" part=\"0\" file=\"" + a + "\"/>\n";
  }
  test::writeText(dir / "run.pvd", pvd + "</Collection>\n</VTKFile>\n");
  return dir / "run.pvd";
}

// The whole box, every point inside a part's cells, and the field there.
void expectWhole(const VectorField& f, double scale) {
  EXPECT_EQ(f.bounds().min, glm::vec3(0.0f));
  EXPECT_EQ(f.bounds().max, glm::vec3(4.0f, 1.0f, 1.0f));
  EXPECT_GE(f.dims().x, 9);  // not one part's points alone
  const glm::ivec3 d = f.dims();
  for (int k = 0; k < d.z; ++k)
    for (int j = 0; j < d.y; ++j)
      for (int i = 0; i < d.x; ++i) {
        ASSERT_TRUE(f.valid(i, j, k)) << i << " " << j << " " << k;
        const glm::dvec3 p(f.pointPosition(i, j, k));
        const glm::dvec3 want = scale * test::asymmetric(p);
        const glm::dvec3 got(f.at(i, j, k));
        ASSERT_NEAR(got.x, want.x, 1e-4) << i << " " << j << " " << k;
        ASSERT_NEAR(got.y, want.y, 1e-4) << i << " " << j << " " << k;
        ASSERT_NEAR(got.z, want.z, 1e-4) << i << " " << j << " " << k;
      }
}

TEST(PvdParts, ATimesPartsAreOneFrameInPartOrder) {
  const auto dir = test::scratch();
  const std::vector<PvdFrame> frames = readPvd(writeParts(dir, 2));
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[1].time, 0.5);
  ASSERT_EQ(frames[1].parts.size(), 2u);
  EXPECT_EQ(frames[1].parts[0].filename(), "run_1_0.vti");
  EXPECT_EQ(frames[1].parts[1].filename(), "run_1_1.vtu");
  EXPECT_EQ(frames[1].file(), frames[1].parts[0]);
}

TEST(PvdParts, ATimeOpensWholeAndEveryStepStreamsWhole) {
  const auto dir = test::scratch();
  const auto pvd = writeParts(dir, 3);
  expectWhole(loadField(pvd), 1.0);
  SeriesIndex index = indexSeries(pvd, {});
  ASSERT_EQ(index.times.size(), 3u);
  expectWhole(*index.first, 1.0);
  SeriesReader reader(std::move(index.sources), index.stepOptions, index.first, 3, 1);
  expectWhole(*reader.wait(2), 3.0);
  expectWhole(*reader.wait(1), 2.0);
  EXPECT_NE(reader.name(1).find("1 more part"), std::string::npos) << reader.name(1);
  // A step's identity (what cluster ranks compare) covers every part.
  EXPECT_EQ(reader.identity(1).size, std::filesystem::file_size(dir / "run_1_0.vti") +
                                         std::filesystem::file_size(dir / "run_1_1.vtu"));
}

TEST(PvdParts, BadPartsAreNamed) {
  const auto dir = test::scratch();
  writeParts(dir, 1);
  const auto write = [&](const std::string& entries) {
    test::writeText(dir / "bad.pvd",
                    "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\">"
                    "<Collection>" +
                        entries + "</Collection></VTKFile>\n");
    return dir / "bad.pvd";
  };
  test::expectError(
      [&] {
        readPvd(
            write("<DataSet timestep=\"0\" part=\"1\" file=\"run_0_0.vti\"/>"
                  "<DataSet timestep=\"0\" part=\"1\" file=\"run_0_1.vtu\"/>"));
      },
      {"bad.pvd", "timestep 0 appears twice", "both part 1"});
  test::expectError(
      [&] {
        readPvd(
            write("<DataSet timestep=\"0\" part=\"0\" file=\"run_0_0.vti\"/>"
                  "<DataSet timestep=\"0\" part=\"1\" file=\"./run_0_0.vti\"/>"));
      },
      {"bad.pvd", "run_0_0.vti", "two of its parts"});
  test::expectError(
      [&] { readPvd(write("<DataSet timestep=\"0\" part=\"one\" file=\"run_0_0.vti\"/>")); },
      {"bad.pvd", "part \"one\"", "whole number"});
  // A part that is missing, or not a VTK file, is named with its place.
  test::expectError(
      [&] {
        loadField(
            write("<DataSet timestep=\"0\" part=\"0\" file=\"run_0_0.vti\"/>"
                  "<DataSet timestep=\"0\" part=\"1\" file=\"gone.vtu\"/>"));
      },
      {"bad.pvd", "part 1", "gone.vtu", "no such file"});
  // Parts past twice the memory budget together are refused as they are
  // read: four parts of 192 kB of vectors each under a budget of 1.2 times
  // that, each within it alone; the third passes twice the budget.
  std::string four;
  for (int p = 0; p < 4; ++p) {
    const int extent[6] = {40 * p, 40 * p + 39, 0, 19, 0, 19};
    const std::string name = "big_" + std::to_string(p) + ".vti";
    test::writeRawVti(test::asymmetricImage(extent, {0, 0, 0}, glm::dvec3(0.1)), dir / name);
    four += "<DataSet timestep=\"0\" part=\"" + std::to_string(p) + "\" file=\"" + name + "\"/>";
  }
  LoadOptions small;
  small.memoryBudget = 230400;
  test::expectError([&] { loadField(write(four), small); },
                    {"bad.pvd", "part 2", "field.memory_budget"});
  small.memoryBudget = 2 * 230400;
  EXPECT_NO_THROW(loadField(dir / "bad.pvd", small));
}

}  // namespace
}  // namespace sandstorm
