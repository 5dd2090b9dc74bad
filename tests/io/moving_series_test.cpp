// A series whose steps lie on other grids than the first (a moving or growing
// mesh, an image shifted or at another resolution) plays on the first step's
// grid: each such step resampled onto it, points it does not cover marked
// outside the field, the values those of the field it was written from
// (test::asymmetric, linear, which trilinear interpolation reproduces).
// Before, playback stopped at the first such step.
#include <gtest/gtest.h>

#include <vtkAppendFilter.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "core/io/series_index.h"
#include "core/io/series_reader.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

std::filesystem::path writePvd(const std::filesystem::path& dir,
                               const std::vector<std::string>& files) {
  std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\">\n<Collection>\n";
  for (std::size_t n = 0; n < files.size(); ++n)
    pvd += "<DataSet timestep=\"" + std::to_string(n) + "\" file=\"" + files[n] + "\"/>\n";
  test::writeText(dir / "run.pvd", pvd + "</Collection>\n</VTKFile>\n");
  return dir / "run.pvd";
}

void writeVtu(vtkImageData* image, const std::filesystem::path& path) {
  vtkNew<vtkAppendFilter> grid;
  grid->AddInputData(image);
  grid->Update();
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetInputData(grid->GetOutput());
  w->SetFileName(path.c_str());
  ASSERT_EQ(w->Write(), 1);
}

// `step` on `first`'s grid: outside where x < `from`, the field elsewhere.
void expectOnFirstGrid(const VectorField& step, const VectorField& first, float from) {
  ASSERT_EQ(step.dims(), first.dims());
  ASSERT_EQ(step.bounds().min, first.bounds().min);
  ASSERT_EQ(step.bounds().max, first.bounds().max);
  const glm::ivec3 d = step.dims();
  std::size_t outside = 0;
  for (int k = 0; k < d.z; ++k)
    for (int j = 0; j < d.y; ++j)
      for (int i = 0; i < d.x; ++i) {
        const glm::vec3 p = step.pointPosition(i, j, k);
        if (p.x < from - 1e-4f) {
          EXPECT_FALSE(step.valid(i, j, k)) << "point " << i << " " << j << " " << k;
          ++outside;
          continue;
        }
        ASSERT_TRUE(step.valid(i, j, k)) << "point " << i << " " << j << " " << k;
        const glm::vec3 want = glm::vec3(test::asymmetric(glm::dvec3(p)));
        for (int a = 0; a < 3; ++a)
          EXPECT_NEAR(step.at(i, j, k)[a], want[a], 2e-5f) << "point " << i << " " << j << " " << k;
      }
  EXPECT_GT(outside, 0u);
  EXPECT_EQ(step.invalidCount(), outside);
}

// Step 0 over [0,3]x[0,2]x[0,1] m, 0.5 m apart; step 1 the same box moved
// 1.25 m along x, at twice the resolution.
TEST(MovingSeries, AnImageStepElsewhereIsResampledOntoTheFirstStepsGrid) {
  const auto dir = test::scratch();
  const int first[6] = {0, 6, 0, 4, 0, 2}, second[6] = {0, 12, 0, 8, 0, 4};
  test::writeRawVti(test::asymmetricImage(first, {0, 0, 0}, glm::dvec3(0.5)), dir / "a.vti");
  test::writeRawVti(test::asymmetricImage(second, {1.25, 0, 0}, glm::dvec3(0.25)), dir / "b.vti");
  SeriesIndex index = indexSeries(writePvd(dir, {"a.vti", "b.vti"}), {});
  ASSERT_EQ(index.first->dims(), glm::ivec3(7, 5, 3));

  std::string note;
  const auto step =
      SeriesReader::read(index.sources[1], index.stepOptions, index.first.get(), &note);
  expectOnFirstGrid(*step, *index.first, 1.25f);
  EXPECT_EQ(step->invalidCount(), 3u * 5u * 3u);  // x = 0, 0.5 and 1 m
  for (const char* part : {"b.vti", "a 13x9x5 grid, not the first step's 7x5x3",
                           "resampled onto the first step's grid", "45 of its 105 points"})
    EXPECT_NE(note.find(part), std::string::npos) << part << " in: " << note;

  // Through the reader, as playback asks for it.
  SeriesReader reader(index.sources, index.stepOptions, index.first, 2, 1);
  expectOnFirstGrid(*reader.wait(1), *index.first, 1.25f);
}

// A mesh that moves: its second step's cells 1.25 m along x. The step is
// sampled straight onto the first step's grid; a third step where the mesh
// is back reads exactly as the first did.
TEST(MovingSeries, AMeshThatMovesPlaysOnTheFirstStepsGrid) {
  const auto dir = test::scratch();
  const int extent[6] = {0, 6, 0, 4, 0, 2};
  writeVtu(test::asymmetricImage(extent, {0, 0, 0}, glm::dvec3(0.5)), dir / "a.vtu");
  writeVtu(test::asymmetricImage(extent, {1.25, 0, 0}, glm::dvec3(0.5)), dir / "b.vtu");
  writeVtu(test::asymmetricImage(extent, {0, 0, 0}, glm::dvec3(0.5)), dir / "c.vtu");
  SeriesIndex index = indexSeries(writePvd(dir, {"a.vtu", "b.vtu", "c.vtu"}), {});
  ASSERT_TRUE(index.stepOptions.samplingBox.has_value());
  SeriesReader reader(index.sources, index.stepOptions, index.first, 3, 1);
  expectOnFirstGrid(*reader.wait(1), *index.first, 1.25f);
  const auto back = reader.wait(2);
  ASSERT_EQ(back->dims(), index.first->dims());
  for (std::size_t i = 0; i < back->pointCount(); ++i)
    ASSERT_EQ(back->values()[i], index.first->values()[i]) << "point " << i;
  EXPECT_FALSE(back->hasValidity());
}

}  // namespace
}  // namespace sandstorm
