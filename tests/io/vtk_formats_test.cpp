// Fields written by VTK's own writers load with the right values and the right
// orientation; fields we write read back identically through VTK's readers.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <fstream>
#include <limits>

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkRectilinearGrid.h>
#include <vtkRectilinearGridWriter.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredGrid.h>
#include <vtkStructuredGridWriter.h>
#include <vtkStructuredPointsWriter.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLRectilinearGridWriter.h>
#include <vtkXMLStructuredGridWriter.h>

#include "core/io/field_loader.h"
#include "core/io/vti_writer.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

using test::asymmetric;

// Adds "velocity" (the asymmetric field, active vectors) and "pressure" (a scalar).
void addArrays(vtkDataSet* data) {
  vtkNew<vtkDoubleArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(data->GetNumberOfPoints());
  vtkNew<vtkFloatArray> p;
  p->SetName("pressure");
  p->SetNumberOfTuples(data->GetNumberOfPoints());
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    double x[3];
    data->GetPoint(i, x);
    const glm::dvec3 a = asymmetric({x[0], x[1], x[2]});
    v->SetTuple3(i, a.x, a.y, a.z);
    p->SetValue(i, float(x[0] * x[1]));
  }
  data->GetPointData()->SetVectors(v);
  data->GetPointData()->AddArray(p);
}

vtkNew<vtkImageData> makeImage() {
  vtkNew<vtkImageData> image;
  image->SetDimensions(5, 4, 3);
  image->SetOrigin(-1.0, 2.0, 0.5);
  image->SetSpacing(0.5, 0.25, 2.0);
  addArrays(image);
  return image;
}

// Non-uniform coordinates along each axis.
vtkNew<vtkRectilinearGrid> makeRectilinear() {
  vtkNew<vtkRectilinearGrid> grid;
  const std::vector<double> xs{-2.0, -1.5, -0.25, 0.0, 1.0, 3.0}, ys{1.0, 1.2, 2.0, 2.5},
      zs{0.0, 0.5, 3.0};
  grid->SetDimensions(int(xs.size()), int(ys.size()), int(zs.size()));
  auto coords = [](const std::vector<double>& c) {
    vtkNew<vtkDoubleArray> a;
    for (double v : c)
      a->InsertNextValue(v);
    return a;
  };
  grid->SetXCoordinates(coords(xs));
  grid->SetYCoordinates(coords(ys));
  grid->SetZCoordinates(coords(zs));
  addArrays(grid);
  return grid;
}

// A curvilinear grid that fills the box [0, 4] x [-1, 1] x [2, 3]: points
// stretched towards one corner (x = 4 s^2 and so on).
vtkNew<vtkStructuredGrid> makeStructured() {
  vtkNew<vtkStructuredGrid> grid;
  const int nx = 6, ny = 5, nz = 4;
  grid->SetDimensions(nx, ny, nz);
  vtkNew<vtkPoints> points;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double s = double(i) / (nx - 1), t = double(j) / (ny - 1), u = double(k) / (nz - 1);
        points->InsertNextPoint(4.0 * s * s, -1.0 + 2.0 * std::sqrt(t), 2.0 + u);
      }
  grid->SetPoints(points);
  addArrays(grid);
  return grid;
}

// Every point of `f` holds the asymmetric field at its position, and so do
// samples between the points.
void expectAsymmetric(const VectorField& f, float tolerance) {
  for (int k = 0; k < f.dims().z; ++k)
    for (int j = 0; j < f.dims().y; ++j)
      for (int i = 0; i < f.dims().x; ++i) {
        const glm::vec3 p = f.pointPosition(i, j, k);
        const glm::vec3 expected(asymmetric(glm::dvec3(p)));
        ASSERT_NEAR(glm::length(f.at(i, j, k) - expected), 0.0f, tolerance)
            << "at point " << i << " " << j << " " << k;
      }
  const glm::vec3 mid = f.bounds().min + glm::vec3(0.37f, 0.61f, 0.29f) * f.bounds().extent();
  EXPECT_NEAR(glm::length(f.sample(mid) - glm::vec3(asymmetric(glm::dvec3(mid)))), 0.0f, tolerance);
}

void expectImageGrid(const VectorField& f) {
  EXPECT_EQ(f.dims(), glm::ivec3(5, 4, 3));
  EXPECT_EQ(f.bounds().min, glm::vec3(-1.0f, 2.0f, 0.5f));
  EXPECT_EQ(f.bounds().max, glm::vec3(1.0f, 2.75f, 4.5f));
  // Orientation: point (1, 0, 0) is one x-step from the origin and holds x + 1 there.
  EXPECT_FLOAT_EQ(f.at(1, 0, 0).x, -0.5f + 1.0f);
  EXPECT_FLOAT_EQ(f.at(0, 1, 0).y, 2.0f * 2.25f - 2.0f);
  EXPECT_FLOAT_EQ(f.at(0, 0, 1).z, 3.0f * 2.5f + 0.5f);
  expectAsymmetric(f, 1e-5f);
}

TEST(VtkFormats, XmlImageDataInEveryDataMode) {
  const auto dir = test::scratch();
  const auto image = makeImage();
  for (int mode : {vtkXMLWriter::Ascii, vtkXMLWriter::Binary, vtkXMLWriter::Appended}) {
    const auto path = dir / ("mode" + std::to_string(mode) + ".vti");
    vtkNew<vtkXMLImageDataWriter> w;
    w->SetInputData(image);
    w->SetDataMode(mode);
    w->SetFileName(path.c_str());
    ASSERT_EQ(w->Write(), 1);
    LoadReport report;
    const VectorField f = loadField(path, {}, &report);
    expectImageGrid(f);
    EXPECT_EQ(report.arrayName, "velocity");
    EXPECT_FALSE(report.resampled);
    ASSERT_EQ(report.available.size(), 2u);
  }
}

TEST(VtkFormats, LegacyStructuredPointsAsciiAndBinary) {
  const auto dir = test::scratch();
  const auto image = makeImage();
  for (bool binary : {false, true}) {
    const auto path = dir / (binary ? "binary.vtk" : "ascii.vtk");
    ASSERT_TRUE(test::writeStructuredPoints(image, path, binary));
    expectImageGrid(loadField(path));
  }
}

TEST(VtkFormats, RectilinearGridsAreResampledThroughVtk) {
  const auto dir = test::scratch();
  const auto grid = makeRectilinear();
  const auto legacyAscii = dir / "ascii.vtk", legacyBinary = dir / "binary.vtk",
             xml = dir / "grid.vtr";
  {
    vtkNew<vtkRectilinearGridWriter> w;
    w->SetInputData(grid);
    w->SetFileName(legacyAscii.c_str());
    ASSERT_EQ(w->Write(), 1);
    w->SetFileName(legacyBinary.c_str());
    w->SetFileTypeToBinary();
    ASSERT_EQ(w->Write(), 1);
    vtkNew<vtkXMLRectilinearGridWriter> x;
    x->SetInputData(grid);
    x->SetFileName(xml.c_str());
    ASSERT_EQ(x->Write(), 1);
  }
  for (const auto& path : {legacyAscii, legacyBinary, xml}) {
    LoadReport report;
    const VectorField f = loadField(path, {}, &report);
    EXPECT_TRUE(report.resampled);
    EXPECT_EQ(f.dims(), glm::ivec3(6, 4, 3)) << path;
    // vtkResampleToImage keeps its samples a hair (~1e-6 relative) inside the bounds.
    EXPECT_NEAR(glm::length(f.bounds().min - glm::vec3(-2.0f, 1.0f, 0.0f)), 0.0f, 1e-4f);
    EXPECT_NEAR(glm::length(f.bounds().max - glm::vec3(3.0f, 2.5f, 3.0f)), 0.0f, 1e-4f);
    expectAsymmetric(f, 1e-4f);
    LoadOptions finer;
    finer.resolution = {11, 7, 5};
    const VectorField g = loadField(path, finer);
    EXPECT_EQ(g.dims(), glm::ivec3(11, 7, 5));
    expectAsymmetric(g, 1e-4f);
  }
}

TEST(VtkFormats, StructuredGridsAreResampledThroughVtk) {
  const auto dir = test::scratch();
  const auto grid = makeStructured();
  const auto legacy = dir / "grid.vtk", xml = dir / "grid.vts";
  {
    vtkNew<vtkStructuredGridWriter> w;
    w->SetInputData(grid);
    w->SetFileName(legacy.c_str());
    w->SetFileTypeToBinary();
    ASSERT_EQ(w->Write(), 1);
    vtkNew<vtkXMLStructuredGridWriter> x;
    x->SetInputData(grid);
    x->SetFileName(xml.c_str());
    ASSERT_EQ(x->Write(), 1);
  }
  for (const auto& path : {legacy, xml}) {
    LoadOptions o;
    o.resolution = {9, 5, 3};
    const VectorField f = loadField(path, o);
    EXPECT_NEAR(glm::length(f.bounds().min - glm::vec3(0.0f, -1.0f, 2.0f)), 0.0f, 1e-4f) << path;
    EXPECT_NEAR(glm::length(f.bounds().max - glm::vec3(4.0f, 1.0f, 3.0f)), 0.0f, 1e-4f);
    expectAsymmetric(f, 1e-4f);
  }
}

// The scalar array "pressure" = x y at every point of `f` (bilinear, so
// resampling by trilinear interpolation keeps it exact).
void expectPressure(const VectorField& f, float tolerance) {
  const VectorField::Scalars* p = f.findScalars("pressure");
  ASSERT_TRUE(p) << "arrays: " << f.scalarNames();
  for (int k = 0; k < f.dims().z; ++k)
    for (int j = 0; j < f.dims().y; ++j)
      for (int i = 0; i < f.dims().x; ++i) {
        const glm::vec3 x = f.pointPosition(i, j, k);
        ASSERT_NEAR(p->values[f.index(i, j, k)], x.x * x.y, tolerance)
            << "at point " << i << " " << j << " " << k;
      }
}

TEST(VtkFormats, ScalarArraysComeWithTheFieldInEveryFormat) {
  const auto dir = test::scratch();
  const auto image = makeImage();
  const auto rect = makeRectilinear();
  {
    vtkNew<vtkXMLImageDataWriter> vti;
    vti->SetInputData(image);
    vti->SetFileName((dir / "image.vti").c_str());
    ASSERT_EQ(vti->Write(), 1);
    vtkNew<vtkStructuredPointsWriter> vtk;
    vtk->SetInputData(image);
    vtk->SetFileName((dir / "image.vtk").c_str());
    ASSERT_EQ(vtk->Write(), 1);
    vtkNew<vtkXMLRectilinearGridWriter> vtr;
    vtr->SetInputData(rect);
    vtr->SetFileName((dir / "grid.vtr").c_str());
    ASSERT_EQ(vtr->Write(), 1);
  }
  for (const char* name : {"image.vti", "image.vtk", "grid.vtr"}) {
    SCOPED_TRACE(name);
    const VectorField f = loadField(dir / name);
    ASSERT_EQ(f.scalars().size(), 1u) << f.scalarNames();  // the vectors are not a scalar
    expectPressure(f, 1e-4f);
    LoadOptions finer;
    finer.resolution = {9, 7, 5};
    expectPressure(loadField(dir / name, finer), 1e-4f);
  }
}

TEST(VtkFormats, CellScalarArraysMoveToThePointsAndNonFiniteValuesBecomeZero) {
  const auto dir = test::scratch();
  vtkNew<vtkImageData> image;
  image->SetDimensions(3, 3, 2);
  addArrays(image);
  vtkNew<vtkFloatArray> density;
  density->SetName("density");
  density->SetNumberOfTuples(image->GetNumberOfCells());
  density->FillValue(1.25f);
  image->GetCellData()->AddArray(density);
  vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("pressure"))
      ->SetValue(4, std::numeric_limits<float>::infinity());
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(image);
  w->SetFileName((dir / "cells.vti").c_str());
  ASSERT_EQ(w->Write(), 1);
  LoadReport report;
  const VectorField f = loadField(dir / "cells.vti", {}, &report);
  const VectorField::Scalars* d = f.findScalars("density");
  ASSERT_TRUE(d) << f.scalarNames();
  for (const float v : d->values)
    EXPECT_FLOAT_EQ(v, 1.25f);
  const VectorField::Scalars* p = f.findScalars("pressure");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->values[4], 0.0f);
  EXPECT_EQ(report.nonFinite, 1u);
}

TEST(VtkFormats, ImageDataResampledToAnotherResolution) {
  const auto dir = test::scratch();
  const auto path = dir / "image.vti";
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(makeImage());
  w->SetFileName(path.c_str());
  ASSERT_EQ(w->Write(), 1);
  LoadOptions o;
  o.resolution = {9, 7, 5};
  LoadReport report;
  const VectorField f = loadField(path, o, &report);
  EXPECT_TRUE(report.resampled);
  EXPECT_EQ(f.dims(), glm::ivec3(9, 7, 5));
  expectAsymmetric(f, 1e-4f);
}

TEST(VtkFormats, OurVtiReadsBackThroughVtkUnchanged) {
  const auto dir = test::scratch();
  std::vector<glm::vec3> values;
  const glm::ivec3 dims(4, 3, 5);
  const Box box{{-3.0f, 0.0f, 1.0f}, {3.0f, 1.0f, 9.0f}};
  VectorField f(box, dims);
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i)
        f.at(i, j, k) = glm::vec3(asymmetric(glm::dvec3(f.pointPosition(i, j, k)))) +
                        glm::vec3(1e-3f * float(i * 7 + j * 3 + k));
  const auto path = dir / "ours.vti";
  writeVti(path, f, "wind");

  vtkNew<vtkXMLImageDataReader> r;
  r->SetFileName(path.c_str());
  r->Update();
  vtkImageData* image = r->GetOutput();
  int d[3];
  image->GetDimensions(d);
  EXPECT_EQ(glm::ivec3(d[0], d[1], d[2]), dims);
  double origin[3], spacing[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  EXPECT_FLOAT_EQ(float(origin[0]), -3.0f);
  EXPECT_FLOAT_EQ(float(origin[2]), 1.0f);
  EXPECT_FLOAT_EQ(float(spacing[0]), 2.0f);
  EXPECT_FLOAT_EQ(float(spacing[1]), 0.5f);
  EXPECT_FLOAT_EQ(float(spacing[2]), 2.0f);
  vtkDataArray* a = image->GetPointData()->GetVectors();
  ASSERT_NE(a, nullptr);
  EXPECT_STREQ(a->GetName(), "wind");
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) {
        int ijk[3] = {i, j, k};
        const vtkIdType id = image->ComputePointId(ijk);
        double t[3];
        a->GetTuple(id, t);
        const glm::vec3 v = f.at(i, j, k);
        EXPECT_EQ(float(t[0]), v.x);
        EXPECT_EQ(float(t[1]), v.y);
        EXPECT_EQ(float(t[2]), v.z);
      }
  // And our reader gives back the very same floats.
  const VectorField g = loadField(path);
  for (std::size_t i = 0; i < f.pointCount(); ++i)
    EXPECT_EQ(g.values()[i], f.values()[i]);
}

// Each compression writes raw appended data (64-bit headers) that reads back
// to the very same floats; a masked point reads as zero, and only the
// unmasked non-finite vector is counted.
TEST(VtkFormats, EveryCompressionOfOurVtiReadsBackTheSameFloats) {
  const glm::ivec3 dims(6, 5, 4);
  VectorField f({{0.0f, 0.0f, 0.0f}, {5.0f, 4.0f, 3.0f}}, dims);
  std::vector<std::uint8_t> valid(f.pointCount(), 1);
  for (std::size_t i = 0; i < f.pointCount(); ++i)
    f.values()[i] = glm::vec3(std::sin(float(i)), 1e-3f * float(i), -float(i * i));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  f.values()[7] = glm::vec3(nan, 0.0f, 0.0f);  // masked
  valid[7] = 0;
  f.values()[11] = glm::vec3(0.0f, nan, 0.0f);  // counted
  valid[3] = 0;
  f.setValidity(valid);
  const std::pair<VtiCompression, const char*> kinds[] = {
      {VtiCompression::ZLib, "compressor=\"vtkZLibDataCompressor\""},
      {VtiCompression::LZ4, "compressor=\"vtkLZ4DataCompressor\""},
      {VtiCompression::None, nullptr}};
  for (const auto& [compression, compressor] : kinds) {
    const auto path = test::scratch() / "compressed.vti";
    writeVti(path, f, "wind", compression);
    const std::string text = test::readAll(path);
    EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
    EXPECT_NE(text.find("header_type=\"UInt64\""), std::string::npos);
    EXPECT_EQ(text.find("compressor="), compressor ? text.find(compressor) : std::string::npos);
    LoadReport report;
    const VectorField g = loadField(path, {}, &report);
    EXPECT_EQ(report.nonFinite, 1u);
    for (std::size_t i = 0; i < f.pointCount(); ++i) {
      const bool zero = i == 3 || i == 7 || i == 11;
      EXPECT_EQ(g.values()[i], zero ? glm::vec3(0.0f) : f.values()[i]) << i;
      EXPECT_EQ(g.validity()[i], valid[i]) << i;
    }
  }
  EXPECT_EQ(vtiCompressionNamed("lz4", "--compression"), VtiCompression::LZ4);
  test::expectError([] { vtiCompressionNamed("gzip", "--compression"); },
                    {"--compression", "'gzip'", "zlib, lz4 or none"});
}

// Writes image data as VTK XML (.vti) with VTK's own writer; false on failure.
bool writeWithVtk(vtkImageData* image, const std::filesystem::path& path) {
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(image);
  w->SetFileName(path.c_str());
  return w->Write() == 1;
}

// A float array of `tuples` x `components`, every value `value`.
vtkSmartPointer<vtkFloatArray> filledArray(const char* name, int components, vtkIdType tuples,
                                           float value) {
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  a->Fill(value);
  return a;
}

// 3x3x3 image data with addArrays' arrays and a second vector array, "wind" (2, 2, 2).
vtkSmartPointer<vtkImageData> imageWithWind() {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(3, 3, 3);
  addArrays(image);
  image->GetPointData()->AddArray(filledArray("wind", 3, 27, 2.0f));
  return image;
}

TEST(VtkFormats, ArraysAreChosenByNameAndListedWhenWrong) {
  const auto dir = test::scratch();
  vtkSmartPointer<vtkImageData> image = imageWithWind();
  image->GetCellData()->AddArray(filledArray("cellvel", 3, 8, 4.0f));
  image->GetPointData()->SetActiveVectors(nullptr);
  const auto path = dir / "arrays.vti";
  ASSERT_TRUE(writeWithVtk(image, path));

  test::expectError([&] { loadField(path); },
                    {path.string(), "several vector arrays", "'velocity' (3 components)",
                     "'wind' (3 components)", "'pressure' (1 component)"});
  LoadOptions o;
  o.arrayName = "wind";
  EXPECT_EQ(loadField(path, o).at(1, 1, 1), glm::vec3(2.0f));
  o.arrayName = "pressure";
  test::expectError([&] { loadField(path, o); },
                    {path.string(), "'pressure' has 1 component", "expected a 3-component"});
  o.arrayName = "vorticity";
  test::expectError([&] { loadField(path, o); },
                    {path.string(), "no array named 'vorticity'", "'velocity' (3 components)",
                     "'cellvel' (3 components, cell data)"});
  o.arrayName = "cellvel";  // cell data, moved to the points by VTK
  EXPECT_NEAR(glm::length(loadField(path, o).at(2, 0, 1) - glm::vec3(4.0f)), 0.0f, 1e-6f);
}

// A 2D simulation's velocity, two components: read as (x, y, 0), found by
// itself where it is the only such array, or named; in cell data it moves to
// the points. Two of them are asked for.
TEST(VtkFormats, ATwoComponentVelocityIsReadAsXAndYWithZZero) {
  const auto dir = test::scratch();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(3, 4, 1);
  vtkNew<vtkFloatArray> uv;
  uv->SetName("U");
  uv->SetNumberOfComponents(2);
  uv->SetNumberOfTuples(12);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 3; ++i)
      uv->SetTuple2(i + 3 * j, double(i), 2.0 * j);
  image->GetPointData()->AddArray(uv);
  const auto path = dir / "plane.vti";
  ASSERT_TRUE(writeWithVtk(image, path));
  LoadReport report;
  const VectorField f = loadField(path, {}, &report);
  ASSERT_EQ(f.dims(), glm::ivec3(3, 4, 1));
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(f.at(i, j, 0), glm::vec3(float(i), 2.0f * j, 0.0f)) << i << " " << j;
  EXPECT_EQ(report.arrayName, "U");
  EXPECT_TRUE(std::any_of(report.notes.begin(), report.notes.end(), [](const std::string& n) {
    return n.find("'U' has two components") != std::string::npos;
  }));
  LoadOptions named;
  named.arrayName = "U";
  EXPECT_EQ(loadField(path, named).at(2, 3, 0), glm::vec3(2.0f, 6.0f, 0.0f));

  // In cell data: the mean of the cells around each point, as any cell array.
  auto cells = vtkSmartPointer<vtkImageData>::New();
  cells->SetDimensions(3, 3, 1);
  cells->GetCellData()->AddArray(filledArray("Uc", 2, 4, 3.0f));
  const auto cellPath = dir / "cells.vti";
  ASSERT_TRUE(writeWithVtk(cells, cellPath));
  EXPECT_EQ(loadField(cellPath).at(1, 1, 0), glm::vec3(3.0f, 3.0f, 0.0f));

  // Two of them: which?
  vtkNew<vtkFloatArray> other;
  other->DeepCopy(uv);
  other->SetName("V");
  image->GetPointData()->AddArray(other);
  const auto two = dir / "two.vti";
  ASSERT_TRUE(writeWithVtk(image, two));
  test::expectError([&] { loadField(two); },
                    {two.string(), "several of 2 components", "'U' (2 components)",
                     "'V' (2 components)", "--array"});

  // u and v as arrays of one component each, no w: joined, z 0.
  auto scalars = vtkSmartPointer<vtkImageData>::New();
  scalars->SetDimensions(3, 4, 1);
  scalars->GetPointData()->AddArray(filledArray("u", 1, 12, 1.5f));
  scalars->GetPointData()->AddArray(filledArray("v", 1, 12, -0.5f));
  const auto uvPath = dir / "uv.vti";
  ASSERT_TRUE(writeWithVtk(scalars, uvPath));
  LoadReport joined;
  EXPECT_EQ(loadField(uvPath, {}, &joined).at(1, 2, 0), glm::vec3(1.5f, -0.5f, 0.0f));
  EXPECT_TRUE(std::any_of(joined.notes.begin(), joined.notes.end(), [](const std::string& n) {
    return n.find("joined from the components 'u', 'v', z 0") != std::string::npos;
  }));
}

// A legacy file cannot mark one of several VECTORS sections active (VTK's
// reader takes the first): the loader asks which. A file that marks one (XML)
// gets it, and the report names the others.
TEST(VtkFormats, SeveralVectorArraysAreAskedForUnlessOneIsMarkedActive) {
  const auto dir = test::scratch();
  const auto legacy = dir / "two.vtk";
  {
    std::ofstream f(legacy);
    f << "# vtk DataFile Version 3.0\ntwo winds\nASCII\nDATASET STRUCTURED_POINTS\n"
         "DIMENSIONS 2 2 2\nORIGIN 0 0 0\nSPACING 1 1 1\nPOINT_DATA 8\nVECTORS wind float\n";
    for (int i = 0; i < 8; ++i)
      f << "1 0 0\n";
    f << "VECTORS gust float\n";
    for (int i = 0; i < 8; ++i)
      f << "0 2 0\n";
  }
  test::expectError([&] { loadField(legacy); },
                    {legacy.string(), "several vector arrays", "--array", "'wind' (3 components)",
                     "'gust' (3 components)"});
  LoadOptions o;
  o.arrayName = "gust";
  EXPECT_EQ(loadField(legacy, o).at(1, 1, 1), glm::vec3(0.0f, 2.0f, 0.0f));

  vtkSmartPointer<vtkImageData> image = imageWithWind();  // "velocity" active, "wind"
  const auto xml = dir / "marked.vti";
  ASSERT_TRUE(writeWithVtk(image, xml));
  LoadReport report;
  loadField(xml, {}, &report);
  EXPECT_EQ(report.arrayName, "velocity");
  bool named = false;
  for (const std::string& note : report.notes)
    named = named || (note.find("'wind'") != std::string::npos &&
                      note.find("'velocity'") != std::string::npos);
  EXPECT_TRUE(named) << "the report names the other vector arrays";
}

TEST(VtkFormats, NonFiniteVectorsBecomeZeroAndAreCounted) {
  const auto dir = test::scratch();
  auto image = makeImage();
  vtkDataArray* v = image->GetPointData()->GetVectors();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  v->SetTuple3(0, nan, 0, 0);
  v->SetTuple3(7, 1, inf, 0);
  v->SetTuple3(20, 0, 0, -inf);
  const auto path = dir / "nan.vti";
  ASSERT_TRUE(writeWithVtk(image, path));
  LoadReport report;
  const VectorField f = loadField(path, {}, &report);
  EXPECT_EQ(report.nonFinite, 3u);
  EXPECT_EQ(f.values()[0], glm::vec3(0.0f));
  EXPECT_EQ(f.values()[7], glm::vec3(0.0f));
  EXPECT_EQ(f.values()[20], glm::vec3(0.0f));
  EXPECT_NE(f.values()[1], glm::vec3(0.0f));
}

}  // namespace
}  // namespace sandstorm
