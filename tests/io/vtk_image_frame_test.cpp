// readVtkImageFrame: a .vti's or .pvti's bounds and points from its header
// alone are the ones the field loaded from it gets (sandstorm FILE frames its
// walls with them while the arrays are read), for any extent, origin and
// spacing VTK's writer puts there; anything the header does not settle gives
// none, and the read then says what is wrong.
#include "core/io/vtk_xml_check.h"

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkRectilinearGrid.h>
#include <vtkXMLRectilinearGridWriter.h>

#include "core/io/field_loader.h"
#include "tests/io/index_files.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

TEST(VtkImageFrame, TheHeadersBoundsAndPointsAreTheLoadedFields) {
  const auto dir = test::scratch();
  struct Case {
    int extent[6];
    glm::dvec3 origin, spacing;
  };
  const Case cases[] = {
      {{0, 6, 0, 4, 0, 2}, {0, 0, 0}, {1, 1, 1}},
      {{2, 8, -3, 1, 5, 9}, {-1.5, 0.25, 2.0}, {0.125, 0.25, 0.5}},
      // Spacings no decimal writes exactly, and a field kilometres from the origin.
      {{0, 12, 0, 6, 0, 3}, {1234567.891, -0.1, 1e-3}, {1.0 / 3.0, 0.1, 7.0 / 9.0}},
      {{0, 9, 0, 9, 0, 0}, {0.5, 0.5, 0.0}, {0.2, 0.2, 1.0}},  // one layer
  };
  int n = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(n);
    const auto path = dir / ("image" + std::to_string(n++) + ".vti");
    test::writeRawVti(test::asymmetricImage(c.extent, c.origin, c.spacing), path);
    // The same grid as the one piece of a parallel image file.
    const auto pvti = std::filesystem::path(path).replace_extension(".pvti");
    test::writePvtiFor(path, pvti);
    for (const auto& file : {path, pvti}) {
      SCOPED_TRACE(file.filename().string());
      const std::optional<VtkImageFrame> frame = readVtkImageFrame(file);
      ASSERT_TRUE(frame);
      const VectorField field = loadField(file, {});
      EXPECT_EQ(frame->dims(), field.dims());
      EXPECT_EQ(frame->bounds().min, field.bounds().min);  // bit for bit
      EXPECT_EQ(frame->bounds().max, field.bounds().max);
    }
  }
}

TEST(VtkImageFrame, WhatTheHeaderDoesNotSettleGivesNone) {
  const auto dir = test::scratch();
  // Another grid type.
  vtkNew<vtkRectilinearGrid> grid;
  grid->SetDimensions(2, 2, 2);
  vtkNew<vtkFloatArray> xs;
  xs->InsertNextValue(0.0f);
  xs->InsertNextValue(1.0f);
  grid->SetXCoordinates(xs);
  grid->SetYCoordinates(xs);
  grid->SetZCoordinates(xs);
  vtkNew<vtkXMLRectilinearGridWriter> w;
  w->SetInputData(grid);
  w->SetFileName((dir / "grid.vtr").c_str());
  ASSERT_EQ(w->Write(), 1);
  EXPECT_FALSE(readVtkImageFrame(dir / "grid.vtr"));
  EXPECT_FALSE(readVtkImageFrame(dir / "absent.vti"));

  const auto header = [&](const std::string& name, const std::string& attributes) {
    const auto path = dir / name;
    test::writeText(path,
                    "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\">\n"
                    "<ImageData " +
                        attributes +
                        ">\n<Piece Extent=\"0 1 0 1 0 1\"></Piece>\n"
                        "</ImageData>\n</VTKFile>\n");
    return path;
  };
  const auto good = header("good.vti", "WholeExtent=\"0 1 0 1 0 1\" Spacing=\"2 2 2\"");
  ASSERT_TRUE(readVtkImageFrame(good));
  EXPECT_EQ(readVtkImageFrame(good)->bounds().max, glm::vec3(2.0f));
  for (const auto& [name, attributes] : std::vector<std::pair<std::string, std::string>>{
           {"no-extent.vti", "Spacing=\"1 1 1\""},
           {"short-extent.vti", "WholeExtent=\"0 1 0 1\""},
           {"empty-extent.vti", "WholeExtent=\"0 1 3 2 0 1\""},
           {"huge-extent.vti", "WholeExtent=\"0 1 0 1 0 2000000000\""},
           {"zero-spacing.vti", "WholeExtent=\"0 1 0 1 0 1\" Spacing=\"1 0 1\""},
           {"negative-spacing.vti", "WholeExtent=\"0 1 0 1 0 1\" Spacing=\"1 1 -1\""},
           {"nan-origin.vti", "WholeExtent=\"0 1 0 1 0 1\" Origin=\"0 nan 0\""},
           {"two-numbers.vti", "WholeExtent=\"0 1 0 1 0 1\" Origin=\"0 1\""},
           {"four-numbers.vti", "WholeExtent=\"0 1 0 1 0 1\" Spacing=\"1 1 1 1\""},
           {"turned.vti", "WholeExtent=\"0 1 0 1 0 1\" Direction=\"0 1 0 1 0 0 0 0 1\""},
           {"unquoted.vti", "WholeExtent=0"}}) {
    EXPECT_FALSE(readVtkImageFrame(header(name, attributes))) << name;
  }
  // A parallel image file's header frames it as a .vti's does; its element
  // must be the one its VTKFile type names.
  const auto parallel = [&](const std::string& name, const std::string& type,
                            const std::string& element) {
    const auto path = dir / name;
    test::writeText(path, "<VTKFile type=\"" + type + "\" version=\"0.1\">\n<" + element +
                              " WholeExtent=\"0 2 0 1 0 1\" Origin=\"1 0 0\" Spacing=\"0.5 1 1\">\n"
                              "<Piece Extent=\"0 2 0 1 0 1\" Source=\"p.vti\"/>\n</" +
                              element + ">\n</VTKFile>\n");
    return path;
  };
  const auto pvti = parallel("good.pvti", "PImageData", "PImageData");
  ASSERT_TRUE(readVtkImageFrame(pvti));
  EXPECT_EQ(readVtkImageFrame(pvti)->bounds().max, glm::vec3(2.0f, 1.0f, 1.0f));
  EXPECT_FALSE(readVtkImageFrame(parallel("mixed.pvti", "PImageData", "ImageData")));
  EXPECT_FALSE(readVtkImageFrame(parallel("mixed.vti", "ImageData", "PImageData")));
  EXPECT_FALSE(readVtkImageFrame(parallel("grid.pvtr", "PRectilinearGrid", "PRectilinearGrid")));
  test::writeText(dir / "text.vti", "not XML at all");
  EXPECT_FALSE(readVtkImageFrame(dir / "text.vti"));
  test::writeText(dir / "cut.vti", "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\"><Image");
  EXPECT_FALSE(readVtkImageFrame(dir / "cut.vti"));
}

}  // namespace
}  // namespace sandstorm
