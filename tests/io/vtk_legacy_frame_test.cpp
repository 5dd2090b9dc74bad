// readVtkLegacyFrame: a legacy .vtk STRUCTURED_POINTS file's bounds and points
// from its header alone are the ones the field loaded from it gets (sandstorm
// FILE frames its walls with them while the file is read), in ASCII and
// BINARY as VTK's writer puts them and in the keyword orders the format
// allows; anything the header does not settle gives none, and the read then
// says what is wrong.
#include "core/io/vtk_legacy_parser.h"

#include <string>
#include <utility>
#include <vector>

#include "core/io/field_loader.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

void expectFrameIsTheLoadedFields(const std::filesystem::path& file) {
  SCOPED_TRACE(file.filename().string());
  const std::optional<VtkImageFrame> frame = readVtkLegacyFrame(file);
  ASSERT_TRUE(frame);
  const VectorField field = loadField(file, {});
  EXPECT_EQ(frame->dims(), field.dims());
  EXPECT_EQ(frame->bounds().min, field.bounds().min);  // bit for bit
  EXPECT_EQ(frame->bounds().max, field.bounds().max);
}

TEST(VtkLegacyFrame, TheHeadersBoundsAndPointsAreTheLoadedFields) {
  const auto dir = test::scratch();
  struct Case {
    glm::ivec3 dims;
    glm::dvec3 origin, spacing;
  };
  const Case cases[] = {
      {{7, 5, 3}, {0, 0, 0}, {1, 1, 1}},
      {{7, 5, 5}, {-1.5, 0.25, 2.0}, {0.125, 0.25, 0.5}},
      // Spacings no decimal writes exactly, and a field kilometres from the origin.
      {{13, 7, 4}, {1234567.891, -0.1, 1e-3}, {1.0 / 3.0, 0.1, 7.0 / 9.0}},
      {{10, 10, 1}, {0.5, 0.5, 0.0}, {0.2, 0.2, 1.0}},  // one layer
  };
  int n = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(n);
    for (const bool binary : {false, true}) {
      const auto path = dir / ("image" + std::to_string(n) + (binary ? "-binary" : "") + ".vtk");
      const int extent[6] = {0, c.dims.x - 1, 0, c.dims.y - 1, 0, c.dims.z - 1};
      ASSERT_TRUE(test::writeStructuredPoints(test::asymmetricImage(extent, c.origin, c.spacing),
                                              path, binary));
      expectFrameIsTheLoadedFields(path);
    }
    ++n;
  }
}

// The geometry's keywords in any order, ASPECT_RATIO for SPACING, a
// dataset-level FIELD among them and the cell data first: the frame is the
// one the read makes of the same lines.
TEST(VtkLegacyFrame, EveryOrderTheFormatAllowsFramesAsTheReadDoes) {
  const auto dir = test::scratch();
  const std::string points =
      "POINT_DATA 8\nVECTORS velocity float\n"
      "1 0 0  1 0 0  1 0 0  1 0 0  0 1 0  0 1 0  0 1 0  0 1 0\n";
  const std::vector<std::pair<std::string, std::string>> files = {
      {"spacing-first.vtk", "SPACING 0.5 2 0.25\nORIGIN -1 0.1 3\nDIMENSIONS 2 2 2\n" + points},
      {"aspect-ratio.vtk", "DIMENSIONS 2 2 2\nASPECT_RATIO 0.5 2 0.25\nORIGIN -1 0.1 3\n" + points},
      {"field-data.vtk",
       "FIELD FieldData 1\nTIME 1 1 double\n2.5\nDIMENSIONS 2 2 2\nORIGIN -1 0.1 3\n"
       "SPACING 0.5 2 0.25\n" +
           points},
      {"cells-first.vtk",
       "DIMENSIONS 2 2 2\nORIGIN -1 0.1 3\nSPACING 0.5 2 0.25\nCELL_DATA 1\n"
       "SCALARS pressure float 1\nLOOKUP_TABLE default\n101325\n" +
           points},
  };
  for (const auto& [name, geometry] : files) {
    const auto path = dir / name;
    test::writeText(
        path,
        "# vtk DataFile Version 3.0\nhand written\nASCII\nDATASET STRUCTURED_POINTS\n" + geometry);
    expectFrameIsTheLoadedFields(path);
    EXPECT_EQ(readVtkLegacyFrame(path)->bounds().max, glm::vec3(-0.5f, 2.1f, 3.25f));
  }
}

TEST(VtkLegacyFrame, WhatTheHeaderDoesNotSettleGivesNone) {
  const auto dir = test::scratch();
  const auto file = [&](const std::string& name, const std::string& text) {
    test::writeText(dir / name, text);
    return dir / name;
  };
  const std::string head = "# vtk DataFile Version 3.0\nx\nASCII\nDATASET ";
  const std::string data = "POINT_DATA 1\nVECTORS v float\n1 0 0\n";
  const std::string data2 = "POINT_DATA 2\nVECTORS v float\n1 0 0 1 0 0\n";
  // Other datasets: framed after their read.
  EXPECT_FALSE(readVtkLegacyFrame(
      file("rectilinear.vtk", head +
                                  "RECTILINEAR_GRID\nDIMENSIONS 1 1 1\nX_COORDINATES 1 float\n0\n"
                                  "Y_COORDINATES 1 float\n0\nZ_COORDINATES 1 float\n0\n" +
                                  data)));
  EXPECT_FALSE(readVtkLegacyFrame(
      file("structured.vtk",
           head + "STRUCTURED_GRID\nDIMENSIONS 1 1 1\nPOINTS 1 float\n0 0 0\n" + data)));
  EXPECT_FALSE(readVtkLegacyFrame(
      file("unstructured.vtk", head + "UNSTRUCTURED_GRID\nPOINTS 1 float\n0 0 0\n" + data)));
  EXPECT_FALSE(readVtkLegacyFrame(dir / "absent.vtk"));
  EXPECT_FALSE(readVtkLegacyFrame(file("text.vtk", "not a VTK file at all\n")));
  const std::string sp = head + "STRUCTURED_POINTS\n";
  ASSERT_TRUE(readVtkLegacyFrame(file("good.vtk", sp + "DIMENSIONS 1 1 1\n" + data)));
  for (const auto& [name, geometry] : std::vector<std::pair<std::string, std::string>>{
           {"no-dimensions.vtk", "ORIGIN 0 0 0\nSPACING 1 1 1\n" + data},
           {"zero-dimension.vtk", "DIMENSIONS 2 0 2\n" + data},
           {"two-dimensions.vtk", "DIMENSIONS 2 2\n" + data},
           {"huge-dimension.vtk", "DIMENSIONS 1 1 2000000000\n" + data},
           {"zero-spacing.vtk", "DIMENSIONS 2 2 2\nSPACING 1 0 1\n" + data},
           {"negative-spacing.vtk", "DIMENSIONS 2 2 2\nSPACING 1 1 -1\n" + data},
           {"nan-origin.vtk", "DIMENSIONS 1 1 1\nORIGIN 0 nan 0\n" + data},
           {"misspelt.vtk", "DIMENSIONS 1 1 1\nORIGN 0 0 0\n" + data},
           // The file ends inside the geometry: "0.2" may be the start of "0.25".
           {"cut.vtk", "DIMENSIONS 2 2 2\nSPACING 1 1 0.2"},
           {"no-data.vtk", "DIMENSIONS 2 2 2\nSPACING 1 1 1\n"}}) {
    EXPECT_FALSE(readVtkLegacyFrame(file(name, sp + geometry))) << name;
  }
  // A geometry that does not end within the bytes the frame reads: a FIELD
  // of more values than they hold. The read still loads it.
  std::string many = "FIELD FieldData 1\nnoise 1 20000 float\n";
  for (int i = 0; i < 20000; ++i)
    many += "0.125 ";
  ASSERT_GT(many.size(), kLegacyFrameBytes);
  const auto long_ = file("long-geometry.vtk", sp + many + "\nDIMENSIONS 2 1 1\n" + data2);
  EXPECT_FALSE(readVtkLegacyFrame(long_));
  EXPECT_EQ(loadField(long_, {}).dims(), glm::ivec3(2, 1, 1));
}

}  // namespace
}  // namespace sandstorm
