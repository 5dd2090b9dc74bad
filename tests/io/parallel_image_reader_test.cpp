// ParallelImageReader (a .pvti's pieces read as .vti files are and put into
// the image over the cores) makes the image VTK's own .pvti reader makes:
// the same extent, origin and spacing, and every point and cell array with
// the same name, type and bytes, for pieces with and without ghost levels
// and for one piece that is the whole image (its arrays lent, not copied).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLPImageDataReader.h>

#include "core/io/parallel_image_reader.h"
#include "core/io/vtk_xml_check.h"
#include "tests/io/index_files.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

namespace fs = std::filesystem;

// An image over `extent` with point vectors, a double and an int point
// array and a cell array, each value a function of its point's (cell's)
// indices in the whole grid: a piece over part of the extent holds the
// whole image's values there.
vtkNew<vtkImageData> image(const int (&extent)[6]) {
  vtkNew<vtkImageData> im;
  im->SetExtent(extent[0], extent[1], extent[2], extent[3], extent[4], extent[5]);
  im->SetOrigin(-1.5, 0.25, 2.0);
  im->SetSpacing(0.125, 0.25, 1.0 / 3.0);
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(im->GetNumberOfPoints());
  vtkNew<vtkDoubleArray> pressure;
  pressure->SetName("pressure");
  pressure->SetNumberOfTuples(im->GetNumberOfPoints());
  vtkNew<vtkIntArray> id;
  id->SetName("id");
  id->SetNumberOfTuples(im->GetNumberOfPoints());
  vtkNew<vtkFloatArray> heat;
  heat->SetName("heat");
  heat->SetNumberOfTuples(im->GetNumberOfCells());
  vtkIdType point = 0, cell = 0;
  for (int k = extent[4]; k <= extent[5]; ++k)
    for (int j = extent[2]; j <= extent[3]; ++j)
      for (int i = extent[0]; i <= extent[1]; ++i, ++point) {
        const double g = double(i) + 100.0 * double(j) + 10000.0 * double(k);
        v->SetTuple3(point, std::sin(0.01 * g), 1.0 + 1e-3 * g, -0.5 * double(i % 7));
        pressure->SetValue(point, 1e5 + std::sqrt(std::abs(g)));
        id->SetValue(point, int(g) * 3 + 1);
        if (i < extent[1] && j < extent[3] && k < extent[5])
          heat->SetValue(cell++, float(g) * 0.5f);
      }
  im->GetPointData()->AddArray(v);
  im->GetPointData()->AddArray(pressure);
  im->GetPointData()->AddArray(id);
  im->GetCellData()->AddArray(heat);
  return im;
}

// The whole extent cut into `nx` x `nz` pieces, each grown by `ghosts`
// points on every side within the whole (as a run with ghost levels writes
// them), each piece a raw .vti beside the .pvti that names them.
std::vector<fs::path> writePieces(const int (&whole)[6], const fs::path& pvti, int nx, int nz,
                                  int ghosts) {
  std::vector<fs::path> files;
  std::ostringstream text;
  text << "<VTKFile type=\"PImageData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
       << "<PImageData WholeExtent=\"" << whole[0] << " " << whole[1] << " " << whole[2] << " "
       << whole[3] << " " << whole[4] << " " << whole[5] << "\" GhostLevel=\"" << ghosts
       << "\" Origin=\"-1.5 0.25 2\" Spacing=\"0.125 0.25 0.33333333333333331\">\n"
       << "<PPointData><PDataArray type=\"Float32\" Name=\"velocity\" NumberOfComponents=\"3\"/>"
       << "<PDataArray type=\"Float64\" Name=\"pressure\"/><PDataArray type=\"Int32\" "
          "Name=\"id\"/></PPointData>\n"
       << "<PCellData><PDataArray type=\"Float32\" Name=\"heat\"/></PCellData>\n";
  const auto cut = [](int from, int to, int parts, int p) {
    return from + (to - from) * p / parts;  // pieces share their boundary points
  };
  for (int pz = 0; pz < nz; ++pz)
    for (int px = 0; px < nx; ++px) {
      int e[6] = {
          cut(whole[0], whole[1], nx, px), cut(whole[0], whole[1], nx, px + 1), whole[2], whole[3],
          cut(whole[4], whole[5], nz, pz), cut(whole[4], whole[5], nz, pz + 1)};
      for (int a = 0; a < 3; ++a) {
        e[2 * a] = std::max(whole[2 * a], e[2 * a] - ghosts);
        e[2 * a + 1] = std::min(whole[2 * a + 1], e[2 * a + 1] + ghosts);
      }
      const std::string name =
          pvti.stem().string() + "_" + std::to_string(px) + "_" + std::to_string(pz) + ".vti";
      files.push_back(test::writeRawVti(image(e), pvti.parent_path() / name));
      text << "<Piece Extent=\"" << e[0] << " " << e[1] << " " << e[2] << " " << e[3] << " " << e[4]
           << " " << e[5] << "\" Source=\"" << name << "\"/>\n";
    }
  text << "</PImageData>\n</VTKFile>\n";
  test::writeText(pvti, text.str());
  return files;
}

void expectSameArrays(vtkFieldData* ours, vtkFieldData* vtks, const std::string& where) {
  ASSERT_EQ(ours->GetNumberOfArrays(), vtks->GetNumberOfArrays()) << where;
  for (int i = 0; i < vtks->GetNumberOfArrays(); ++i) {
    vtkDataArray* b = vtks->GetArray(i);
    ASSERT_TRUE(b && b->GetName()) << where << " " << i;
    SCOPED_TRACE(where + " " + b->GetName());
    vtkDataArray* a = ours->GetArray(b->GetName());
    ASSERT_TRUE(a);
    EXPECT_EQ(a->GetDataType(), b->GetDataType());
    EXPECT_EQ(a->GetNumberOfComponents(), b->GetNumberOfComponents());
    ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples());
    const std::size_t bytes =
        std::size_t(b->GetNumberOfValues()) * std::size_t(b->GetDataTypeSize());
    EXPECT_EQ(std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0), bytes), 0);
  }
}

struct Read {
  vtkSmartPointer<vtkImageData> image;
  std::size_t lent = 0, copied = 0, readOverTheCores = 0;
};

Read readOurs(const fs::path& pvti, const std::vector<fs::path>& pieces) {
  vtkNew<ParallelImageReader> reader;
  for (const fs::path& p : pieces)
    reader->addPieceRawArrays(p, checkVtkXml(p, std::size_t{1} << 30).raw);
  reader->SetFileName(pvti.c_str());
  reader->Update();
  Read r;
  r.image = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
  r.lent = reader->arraysLent();
  r.copied = reader->arraysCopied();
  r.readOverTheCores = reader->arraysReadOverTheCores();
  return r;
}

vtkSmartPointer<vtkImageData> readVtks(const fs::path& pvti) {
  vtkNew<vtkXMLPImageDataReader> reader;
  reader->SetFileName(pvti.c_str());
  reader->Update();
  return vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
}

void expectSameImage(vtkImageData* ours, vtkImageData* vtks) {
  ASSERT_TRUE(ours && vtks);
  int a[6], b[6];
  ours->GetExtent(a);
  vtks->GetExtent(b);
  EXPECT_TRUE(std::equal(a, a + 6, b));
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(ours->GetOrigin()[k], vtks->GetOrigin()[k]);
    EXPECT_EQ(ours->GetSpacing()[k], vtks->GetSpacing()[k]);
  }
  expectSameArrays(ours->GetPointData(), vtks->GetPointData(), "points");
  expectSameArrays(ours->GetCellData(), vtks->GetCellData(), "cells");
}

TEST(ParallelImageReader, PiecesMakeTheImageVtksReaderMakes) {
  const fs::path dir = test::scratch();
  const int whole[6] = {0, 39, 2, 31, -3, 16};
  for (const auto& [nx, nz, ghosts] :
       {std::tuple{1, 4, 0}, std::tuple{2, 3, 1}, std::tuple{3, 2, 2}}) {
    SCOPED_TRACE(std::to_string(nx) + " x " + std::to_string(nz) + " pieces, " +
                 std::to_string(ghosts) + " ghost levels");
    const fs::path pvti = dir / ("p" + std::to_string(nx) + std::to_string(nz) + ".pvti");
    const std::vector<fs::path> files = writePieces(whole, pvti, nx, nz, ghosts);
    const Read ours = readOurs(pvti, files);
    vtkSmartPointer<vtkImageData> vtks = readVtks(pvti);
    expectSameImage(ours.image, vtks);
    // And the image is the whole grid's.
    vtkNew<vtkImageData> expected = image(whole);
    expectSameArrays(ours.image->GetPointData(), expected->GetPointData(), "whole grid's points");
    expectSameArrays(ours.image->GetCellData(), expected->GetCellData(), "whole grid's cells");
    EXPECT_EQ(ours.lent, 0u);
    EXPECT_GE(ours.copied, std::size_t(4 * nx * nz)) << "every piece's four arrays copied here";
  }
}

TEST(ParallelImageReader, OnePieceThatIsTheWholeImageLendsItsArrays) {
  const fs::path dir = test::scratch();
  // 48^3 points: a velocity array of 1.3 MB; and one of 36 MB, which the piece
  // reader copies from the file over the cores (HugePageImageReader).
  for (const int side : {48, 144}) {
    SCOPED_TRACE(side);
    const int extent[6] = {0, side - 1, 0, side - 1, 0, side - 1};
    const fs::path vti =
        test::writeRawVti(image(extent), dir / ("whole" + std::to_string(side) + ".vti"));
    const fs::path pvti = fs::path(vti).replace_extension(".pvti");
    test::writePvtiFor(vti, pvti);
    const Read ours = readOurs(pvti, {vti});
    vtkSmartPointer<vtkImageData> vtks = readVtks(pvti);
    ASSERT_TRUE(ours.image && vtks);
    // The pvti declares only the velocity: VTK reads only what it declares.
    EXPECT_EQ(ours.lent, 1u);
    EXPECT_EQ(ours.copied, 0u);
    EXPECT_EQ(ours.readOverTheCores, side == 144 ? 1u : 0u);
    expectSameImage(ours.image, vtks);
  }
}

}  // namespace
}  // namespace sandstorm
