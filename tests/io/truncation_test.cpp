// One file of each format cut at many offsets: every cut either loads exactly
// the field of the whole file (when only trailing white space or closing
// bytes that no reader needs went missing) or throws a clean Error. Never a
// crash, never partial data.
#include <gtest/gtest.h>

#include <openvdb/io/File.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkRectilinearGrid.h>
#include <vtkRectilinearGridWriter.h>
#include <vtkStructuredGrid.h>
#include <vtkStructuredPointsWriter.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLRectilinearGridWriter.h>
#include <vtkXMLStructuredGridWriter.h>

#include "core/io/field_loader.h"
#include "core/io/openvdb_grids.h"
#include "core/io/vdb_writer.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

void addVelocity(vtkDataSet* data) {
  vtkNew<vtkDoubleArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(data->GetNumberOfPoints());
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    double x[3];
    data->GetPoint(i, x);
    const glm::dvec3 a = test::asymmetric({x[0], x[1], x[2]});
    v->SetTuple3(i, a.x, a.y, a.z);
  }
  data->GetPointData()->SetVectors(v);
}

vtkNew<vtkImageData> image() {
  vtkNew<vtkImageData> img;
  img->SetDimensions(4, 3, 3);
  img->SetSpacing(0.5, 1.0, 2.0);
  addVelocity(img);
  return img;
}

vtkNew<vtkRectilinearGrid> rectilinear() {
  vtkNew<vtkRectilinearGrid> grid;
  grid->SetDimensions(3, 3, 2);
  for (int a = 0; a < 3; ++a) {
    vtkNew<vtkDoubleArray> c;
    c->InsertNextValue(0.0);
    c->InsertNextValue(0.3 + a);
    if (a < 2) c->InsertNextValue(4.0);
    if (a == 0) grid->SetXCoordinates(c);
    if (a == 1) grid->SetYCoordinates(c);
    if (a == 2) grid->SetZCoordinates(c);
  }
  addVelocity(grid);
  return grid;
}

vtkNew<vtkStructuredGrid> structured() {
  vtkNew<vtkStructuredGrid> grid;
  grid->SetDimensions(3, 2, 2);
  vtkNew<vtkPoints> pts;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        pts->InsertNextPoint(i * i, j, 2 * k);
  grid->SetPoints(pts);
  addVelocity(grid);
  return grid;
}

template <class Writer, class Data>
void writeVtk(const std::filesystem::path& path, Data& data,
              const std::function<void(Writer*)>& set) {
  vtkNew<Writer> w;
  w->SetInputData(data);
  w->SetFileName(path.c_str());
  set(w);
  ASSERT_EQ(w->Write(), 1);
}

void truncateEverywhere(const std::filesystem::path& full) {
  const VectorField whole = loadField(full);
  const std::string bytes = test::readAll(full);
  std::vector<std::size_t> offsets;
  for (std::size_t i = 0; i < std::min<std::size_t>(bytes.size(), 160); ++i)
    offsets.push_back(i);
  const std::size_t stride = std::max<std::size_t>(1, bytes.size() / 120);
  for (std::size_t i = 160; i < bytes.size(); i += stride)
    offsets.push_back(i);
  for (std::size_t i = bytes.size() > 24 ? bytes.size() - 24 : 0; i < bytes.size(); ++i)
    offsets.push_back(i);
  const auto cut = full.parent_path() / ("cut" + full.extension().string());
  int errors = 0, loaded = 0;
  for (std::size_t n : offsets) {
    test::writeText(cut, bytes.substr(0, n));
    try {
      const VectorField f = loadField(cut);
      ++loaded;
      ASSERT_EQ(f.dims(), whole.dims()) << full << " cut at " << n << " loaded other data";
      for (std::size_t i = 0; i < f.pointCount(); ++i)
        ASSERT_EQ(f.values()[i], whole.values()[i]) << full << " cut at " << n;
    } catch (const Error& e) {
      ++errors;
      ASSERT_NE(std::string(e.what()).find(cut.string()), std::string::npos)
          << "message does not name the file: " << e.what();
    }
  }
  EXPECT_GT(errors, int(offsets.size()) * 8 / 10) << full;
  ::testing::Test::RecordProperty(full.filename().string() + "_loaded_whole", loaded);
}

TEST(Truncation, LegacyVtkAsciiAndBinary) {
  const auto dir = test::scratch();
  auto img = image();
  writeVtk<vtkStructuredPointsWriter>(dir / "ascii.vtk", img,
                                      [](auto* w) { w->SetFileTypeToASCII(); });
  writeVtk<vtkStructuredPointsWriter>(dir / "binary.vtk", img,
                                      [](auto* w) { w->SetFileTypeToBinary(); });
  auto rect = rectilinear();
  writeVtk<vtkRectilinearGridWriter>(dir / "rect.vtk", rect,
                                     [](auto* w) { w->SetFileTypeToBinary(); });
  truncateEverywhere(dir / "ascii.vtk");
  truncateEverywhere(dir / "binary.vtk");
  truncateEverywhere(dir / "rect.vtk");
}

TEST(Truncation, VtkXml) {
  const auto dir = test::scratch();
  auto img = image();
  writeVtk<vtkXMLImageDataWriter>(dir / "appended.vti", img, [](auto*) {});
  writeVtk<vtkXMLImageDataWriter>(dir / "ascii.vti", img, [](auto* w) { w->SetDataModeToAscii(); });
  writeVtk<vtkXMLImageDataWriter>(dir / "binary.vti", img,
                                  [](auto* w) { w->SetDataModeToBinary(); });
  auto rect = rectilinear();
  writeVtk<vtkXMLRectilinearGridWriter>(dir / "grid.vtr", rect, [](auto*) {});
  auto grid = structured();
  writeVtk<vtkXMLStructuredGridWriter>(dir / "grid.vts", grid, [](auto*) {});
  for (const char* name : {"appended.vti", "ascii.vti", "binary.vti", "grid.vtr", "grid.vts"})
    truncateEverywhere(dir / name);
}

TEST(Truncation, OpenVdb) {
  const auto dir = test::scratch();
  VectorField f(Box{{0, 0, 0}, {1, 2, 3}}, {5, 4, 3});
  for (std::size_t i = 0; i < f.pointCount(); ++i)
    f.values()[i] = glm::vec3(float(i), 1.0f, -2.0f);
  writeVdb(dir / "field.vdb", f);
  truncateEverywhere(dir / "field.vdb");
}

TEST(Truncation, EngineFormats) {
  const auto dir = test::scratch();
  std::string fga = "3,2,2,\n0,0,0,\n30,20,20,\n";
  for (int i = 0; i < 12; ++i)
    fga += std::to_string(i) + ".5,-1,2,\n";
  test::writeText(dir / "field.fga", fga);
  truncateEverywhere(dir / "field.fga");
  std::string vf = "VF_V";
  for (std::uint16_t d : {std::uint16_t(3), std::uint16_t(2), std::uint16_t(2)})
    vf.append(reinterpret_cast<const char*>(&d), 2);
  for (int i = 0; i < 12; ++i) {
    const float v[3] = {float(i), 1.0f, 2.0f};
    vf.append(reinterpret_cast<const char*>(v), 12);
  }
  test::writeText(dir / "field.vf", vf);
  truncateEverywhere(dir / "field.vf");
}

}  // namespace
}  // namespace sandstorm
