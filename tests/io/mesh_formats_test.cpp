// Meshes written by VTK's own writers (unstructured grids, polydata, the
// parallel files' pieces with their ghost cells, multiblock files) load with
// the analytic field's values, and the validity mask marks what lies outside
// the mesh.
#include <gtest/gtest.h>

#include <vtkArrayCalculator.h>
#include <vtkCellArray.h>
#include <vtkCompositeDataSet.h>
#include <vtkExtractGrid.h>
#include <vtkExtractRectilinearGrid.h>
#include <vtkExtractUnstructuredGridPiece.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkRTAnalyticSource.h>
#include <vtkRectilinearGrid.h>
#include <vtkStructuredGrid.h>
#include <vtkUnstructuredGridWriter.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLPImageDataWriter.h>
#include <vtkXMLPUnstructuredGridWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLRectilinearGridWriter.h>
#include <vtkXMLStructuredGridWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "core/io/field_loader.h"
#include "core/io/field_sequence.h"
#include "tests/io/io_test_util.h"
#include "tests/io/mesh_test_util.h"

namespace sandstorm {
namespace {

using test::asymmetric;

// Trilinear sampling and tetrahedra both reproduce a linear field: only
// float rounding remains (values up to about 7).
constexpr double kExact = 1e-5;

void writeVtu(vtkUnstructuredGrid* mesh, const std::filesystem::path& path, int mode,
              bool zlib = false) {
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetInputData(mesh);
  w->SetFileName(path.c_str());
  w->SetDataMode(mode);
  if (zlib)
    w->SetCompressorTypeToZLib();
  else
    w->SetCompressorTypeToNone();
  ASSERT_EQ(w->Write(), 1);
}

bool hasNote(const LoadReport& report, const std::string& part) {
  for (const std::string& note : report.notes)
    if (note.find(part) != std::string::npos) return true;
  return false;
}

// An n x n sheet of triangles at height z, cells of dx by dy from (x0, y0),
// carrying the asymmetric field (a PIV plane).
vtkSmartPointer<vtkPolyData> triangleSheet(int n, double x0, double y0, double dx, double dy,
                                           double z) {
  auto sheet = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const glm::dvec3 p(x0 + dx * i, y0 + dy * j, z);
      points->InsertNextPoint(p.x, p.y, p.z);
      const glm::dvec3 a = asymmetric(p);
      v->InsertNextTuple3(a.x, a.y, a.z);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const vtkIdType a = i + (n + 1) * j, b = a + 1, c = a + n + 1, d = c + 1;
      const vtkIdType t1[3] = {a, b, d}, t2[3] = {a, d, c};
      triangles->InsertNextCell(3, t1);
      triangles->InsertNextCell(3, t2);
    }
  sheet->SetPoints(points);
  sheet->SetPolys(triangles);
  sheet->GetPointData()->SetVectors(v);
  return sheet;
}

TEST(MeshFormats, UnstructuredXmlInEveryDataModeWithItsNotchOutside) {
  const auto dir = test::scratch();
  const auto mesh = test::lMesh(4, asymmetric);
  LoadOptions options;
  options.resolution = {21, 21, 11};
  struct Mode {
    const char* name;
    int mode;
    bool zlib;
  };
  for (const Mode m :
       {Mode{"ascii", vtkXMLWriter::Ascii, false}, Mode{"binary", vtkXMLWriter::Binary, false},
        Mode{"appended", vtkXMLWriter::Appended, false},
        Mode{"appended-zlib", vtkXMLWriter::Appended, true}}) {
    SCOPED_TRACE(m.name);
    const auto path = dir / (std::string(m.name) + ".vtu");
    writeVtu(mesh, path, m.mode, m.zlib);
    LoadReport report;
    const VectorField f = loadField(path, options, &report);
    EXPECT_EQ(report.arrayName, "velocity");
    EXPECT_TRUE(report.resampled);
    EXPECT_EQ(report.cells, std::uint64_t(mesh->GetNumberOfCells()));
    EXPECT_EQ(f.dims(), glm::ivec3(21, 21, 11));
    EXPECT_EQ(f.bounds().min, glm::vec3(0.0f));
    EXPECT_EQ(f.bounds().max, glm::vec3(2.0f, 2.0f, 1.0f));
    test::expectL(f, asymmetric, kExact);
    // The notch: 10 x 10 columns of 11 points beyond x = 1 and y = 1.
    EXPECT_EQ(report.outside, std::size_t(10 * 10 * 11));
  }
}

// Without field.resolution a mesh is sampled at its cells' size: the Kuhn
// tetrahedra of a 0.25 m hexahedron have that box, so 9 x 9 x 5 points.
TEST(MeshFormats, AMeshIsSampledAtItsCellsSizeByDefault) {
  const auto dir = test::scratch();
  const auto path = dir / "l.vtu";
  writeVtu(test::lMesh(4, asymmetric), path, vtkXMLWriter::Appended);
  LoadReport report;
  const VectorField f = loadField(path, {}, &report);
  EXPECT_EQ(f.dims(), glm::ivec3(9, 9, 5));
  EXPECT_TRUE(hasNote(report, "field.resolution"));
  test::expectL(f, asymmetric, kExact);
}

// Cell data (a finite-volume code's cell values) becomes point data as
// ParaView's Cell Data to Point Data makes it: each mesh point takes the mean
// of the cells around it. For a field with gradient norm at most L, a point's
// value then differs from the field there by at most L times the farthest
// centroid of its cells; interpolation adds nothing for a linear field.
TEST(MeshFormats, CellDataBecomesPointDataWithinTheMeanOfItsCells) {
  const auto dir = test::scratch();
  const auto mesh = test::lMesh(6, asymmetric, /*cells=*/true);
  const auto path = dir / "cells.vtu";
  writeVtu(mesh, path, vtkXMLWriter::Appended, true);
  // The farthest any cell's centroid lies from one of its points.
  double reach = 0.0;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    mesh->GetCellPoints(c, n, ids);
    glm::dvec3 corners[4], centroid(0.0);
    for (vtkIdType i = 0; i < n; ++i) {
      double x[3];
      mesh->GetPoint(ids[i], x);
      corners[i] = {x[0], x[1], x[2]};
      centroid += corners[i] / double(n);
    }
    for (vtkIdType i = 0; i < n; ++i)
      reach = std::max(reach, glm::length(corners[i] - centroid));
  }
  const double gradient = 3.0;  // the asymmetric field's largest stretch (its z)
  LoadOptions options;
  options.resolution = {13, 13, 7};
  LoadReport report;
  const VectorField f = loadField(path, options, &report);
  EXPECT_TRUE(hasNote(report, "cell data: moved to the points"));
  test::expectL(f, asymmetric, gradient * reach + kExact);
  // Where every cell around a mesh point is its mirror image (an unjittered
  // corner of the box's top face is not; the box's middle is close to), the
  // mean lands near the point: well inside the bound.
  EXPECT_LT(
      glm::length(glm::dvec3(f.at(6, 3, 3)) - asymmetric(glm::dvec3(f.pointPosition(6, 3, 3)))),
      0.5 * gradient * reach);
}

// Polydata carrying vectors on a plane (a PIV sheet): a grid one point thick.
TEST(MeshFormats, PolyDataOnAPlaneGivesAFlatGrid) {
  const auto dir = test::scratch();
  const auto sheet = triangleSheet(6, -1.0, 2.0, 0.5, 0.25, 0.75);
  const auto path = dir / "sheet.vtp";
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetInputData(sheet);
  w->SetFileName(path.c_str());
  ASSERT_EQ(w->Write(), 1);
  LoadOptions options;
  options.resolution = {13, 7, 1};
  const VectorField f = loadField(path, options);
  EXPECT_EQ(f.dims(), glm::ivec3(13, 7, 1));
  EXPECT_EQ(f.invalidCount(), std::size_t(0));
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 13; ++i) {
      const glm::dvec3 p(f.pointPosition(i, j, 0));
      EXPECT_NEAR(p.z, 0.75, 1e-6);
      ASSERT_LE(glm::length(glm::dvec3(f.at(i, j, 0)) - asymmetric(p)), kExact);
    }
  // By default: flat along z, spaced as the triangles' longest sides (0.5 m).
  EXPECT_EQ(loadField(path).dims(), glm::ivec3(7, 4, 1));
}

// Pieces a parallel run wrote, each with a layer of ghost cells it shares with
// its neighbours (VTK's piece extractor and parallel writer, as a simulation
// on three ranks writes them), load as the whole mesh does.
TEST(MeshFormats, ParallelUnstructuredPiecesWithGhostCellsMergeIntoTheWholeMesh) {
  const auto dir = test::scratch();
  const auto mesh = test::lMesh(4, asymmetric);
  const auto whole = dir / "whole.vtu";
  writeVtu(mesh, whole, vtkXMLWriter::Appended);
  vtkNew<vtkExtractUnstructuredGridPiece> pieces;
  pieces->SetInputData(mesh);
  vtkNew<vtkXMLPUnstructuredGridWriter> w;
  w->SetInputConnection(pieces->GetOutputPort());
  const auto path = dir / "parallel.pvtu";
  w->SetFileName(path.c_str());
  w->SetNumberOfPieces(3);
  w->SetStartPiece(0);
  w->SetEndPiece(2);
  w->SetGhostLevel(1);
  ASSERT_EQ(w->Write(), 1);
  ASSERT_TRUE(std::filesystem::exists(dir / "parallel_2.vtu"));
  ASSERT_NE(test::readAll(dir / "parallel_1.vtu").find("vtkGhostType"), std::string::npos);

  LoadOptions options;
  options.resolution = {21, 21, 11};
  LoadReport report;
  const VectorField f = loadField(path, options, &report);
  const VectorField g = loadField(whole, options);
  EXPECT_TRUE(hasNote(report, "3 pieces read at once"));
  EXPECT_GT(report.cells, std::uint64_t(mesh->GetNumberOfCells()));  // the ghosts, twice
  test::expectL(f, asymmetric, kExact);
  ASSERT_EQ(f.pointCount(), g.pointCount());
  for (std::size_t p = 0; p < f.pointCount(); ++p)
    ASSERT_LE(glm::length(f.values()[p] - g.values()[p]), 1e-6f) << "point " << p;
}

// `grid` (structured or rectilinear, 9 x 8 x 10 points) written whole and as
// three pieces along z that share a layer of points, with the index a
// simulation's writer makes: "whole.vts" or "whole.vtr", and "split.pvts" or
// "split.pvtr".
template <class Writer, class Extract>
void writeWholeAndPieces(vtkDataSet* grid, const std::filesystem::path& dir, const std::string& ext,
                         const std::string& type) {
  vtkNew<Writer> whole;
  whole->SetInputData(grid);
  whole->SetFileName((dir / ("whole." + ext)).c_str());
  ASSERT_EQ(whole->Write(), 1);
  std::string index =
      "<VTKFile type=\"P" + type + "\" version=\"0.1\" byte_order=\"LittleEndian\">\n<P" + type +
      " WholeExtent=\"0 8 0 7 0 9\" GhostLevel=\"0\">\n<PPointData><PDataArray "
      "type=\"Float32\" Name=\"velocity\" NumberOfComponents=\"3\"/></PPointData>\n";
  index += ext == "vts"
               ? "<PPoints><PDataArray type=\"Float32\" NumberOfComponents=\"3\"/></PPoints>\n"
               : "<PCoordinates><PDataArray type=\"Float64\"/><PDataArray type=\"Float64\"/>"
                 "<PDataArray type=\"Float64\"/></PCoordinates>\n";
  const int layers[4] = {0, 3, 6, 9};
  for (int p = 0; p < 3; ++p) {
    vtkNew<Extract> extract;
    extract->SetInputData(grid);
    extract->SetVOI(0, 8, 0, 7, layers[p], layers[p + 1]);
    vtkNew<Writer> w;
    w->SetInputConnection(extract->GetOutputPort());
    const std::string name = "split_" + std::to_string(p) + "." + ext;
    w->SetFileName((dir / name).c_str());
    ASSERT_EQ(w->Write(), 1);
    index += "<Piece Extent=\"0 8 0 7 " + std::to_string(layers[p]) + " " +
             std::to_string(layers[p + 1]) + "\" Source=\"" + name + "\"/>\n";
  }
  index += "</P" + type + ">\n</VTKFile>\n";
  test::writeText(dir / ("split.p" + ext), index);
}

void expectSameField(const VectorField& f, const VectorField& g) {
  ASSERT_EQ(f.dims(), g.dims());
  EXPECT_EQ(f.bounds().min, g.bounds().min);
  EXPECT_EQ(f.bounds().max, g.bounds().max);
  EXPECT_EQ(f.invalidCount(), g.invalidCount());
  for (std::size_t p = 0; p < f.pointCount(); ++p)
    ASSERT_LE(glm::length(f.values()[p] - g.values()[p]), 1e-6f) << "point " << p;
}

// A curvilinear and a rectilinear grid in pieces: read several at once and
// resampled as the pieces they are, they load as VTK's reader of the whole
// file makes them: the same grid of points (the pieces' whole extent), the
// same values, the same points outside.
TEST(MeshFormats, StructuredAndRectilinearPiecesLoadAsTheWholeGrid) {
  const auto dir = test::scratch();
  vtkNew<vtkStructuredGrid> curved;
  curved->SetDimensions(9, 8, 10);
  vtkNew<vtkPoints> points;
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 9; ++i)
        points->InsertNextPoint(0.25 * i + 0.05 * k, 0.3 * j + 0.02 * i * std::sin(double(k)),
                                0.2 * k * (1.0 + 0.03 * j));
  curved->SetPoints(points);
  test::addAsymmetricVelocity(curved);
  writeWholeAndPieces<vtkXMLStructuredGridWriter, vtkExtractGrid>(curved, dir, "vts",
                                                                  "StructuredGrid");
  vtkNew<vtkRectilinearGrid> stretched;
  stretched->SetDimensions(9, 8, 10);
  vtkNew<vtkDoubleArray> axes[3];
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < (a == 0 ? 9 : a == 1 ? 8 : 10); ++i)
      axes[a]->InsertNextValue(0.1 * i * i + 0.5 * i + a);
  stretched->SetXCoordinates(axes[0]);
  stretched->SetYCoordinates(axes[1]);
  stretched->SetZCoordinates(axes[2]);
  test::addAsymmetricVelocity(stretched);
  writeWholeAndPieces<vtkXMLRectilinearGridWriter, vtkExtractRectilinearGrid>(stretched, dir, "vtr",
                                                                              "RectilinearGrid");
  for (const char* ext : {"vts", "vtr"}) {
    SCOPED_TRACE(ext);
    LoadReport pieces, whole;
    const VectorField f = loadField(dir / (std::string("split.p") + ext), {}, &pieces);
    const VectorField g = loadField(dir / (std::string("whole.") + ext), {}, &whole);
    EXPECT_TRUE(hasNote(pieces, "3 pieces read at once"));
    EXPECT_TRUE(pieces.blocks.empty());  // pieces, not blocks
    EXPECT_EQ(pieces.sourceDims, glm::ivec3(9, 8, 10));
    expectSameField(f, g);
    LoadOptions finer;
    finer.resolution = {17, 15, 19};
    expectSameField(loadField(dir / (std::string("split.p") + ext), finer),
                    loadField(dir / (std::string("whole.") + ext), finer));
  }
}

// Image data in pieces (VTK's streaming source, pieces by extent).
TEST(MeshFormats, ParallelImagePiecesMergeIntoOneGrid) {
  const auto dir = test::scratch();
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(0, 8, 0, 6, 0, 4);
  vtkNew<vtkArrayCalculator> calc;
  calc->SetInputConnection(source->GetOutputPort());
  calc->AddCoordinateScalarVariable("x", 0);
  calc->AddCoordinateScalarVariable("y", 1);
  calc->AddCoordinateScalarVariable("z", 2);
  calc->SetFunction("(x+1)*iHat + (2*y-2)*jHat + (3*z+0.5)*kHat");
  calc->SetResultArrayName("velocity");
  vtkNew<vtkXMLPImageDataWriter> w;
  w->SetInputConnection(calc->GetOutputPort());
  const auto path = dir / "image.pvti";
  w->SetFileName(path.c_str());
  w->SetNumberOfPieces(3);
  w->SetStartPiece(0);
  w->SetEndPiece(2);
  ASSERT_EQ(w->Write(), 1);
  ASSERT_NE(test::readAll(dir / "image_0.vti"), test::readAll(dir / "image_1.vti"));
  LoadOptions options;
  options.arrayName = "velocity";
  LoadReport report;
  const VectorField f = loadField(path, options, &report);
  EXPECT_EQ(f.dims(), glm::ivec3(9, 7, 5));
  EXPECT_FALSE(report.resampled);
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 7; ++j)
      for (int i = 0; i < 9; ++i)
        ASSERT_LE(glm::length(glm::dvec3(f.at(i, j, k)) - asymmetric(glm::dvec3(i, j, k))), kExact);
}

// A .vtm of an unstructured block and an image block beside it, both
// carrying the array, and a block that does not: the first two make one
// field, the third is named in the report.
TEST(MeshFormats, MultiblockBlocksOfAnyKindMergeIntoOneField) {
  const auto dir = test::scratch();
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(3);
  blocks->SetBlock(0, test::lMesh(4, asymmetric));
  blocks->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), "fluid");
  vtkNew<vtkImageData> box;  // x in [2, 3], beside the L
  box->SetDimensions(5, 9, 5);
  box->SetOrigin(2.0, 0.0, 0.0);
  box->SetSpacing(0.25, 0.25, 0.25);
  test::addAsymmetricVelocity(box);
  blocks->SetBlock(1, box);
  blocks->GetMetaData(1u)->Set(vtkCompositeDataSet::NAME(), "inlet");
  vtkNew<vtkImageData> solid;
  solid->SetDimensions(2, 2, 2);
  solid->SetOrigin(0.0, 0.0, 5.0);
  vtkNew<vtkFloatArray> temperature;
  temperature->SetName("temperature");
  temperature->SetNumberOfTuples(8);
  temperature->Fill(300.0f);
  solid->GetPointData()->AddArray(temperature);
  blocks->SetBlock(2, solid);
  blocks->GetMetaData(2u)->Set(vtkCompositeDataSet::NAME(), "wall");
  const auto path = dir / "case.vtm";
  vtkNew<vtkXMLMultiBlockDataWriter> w;
  w->SetInputData(blocks);
  w->SetFileName(path.c_str());
  ASSERT_EQ(w->Write(), 1);

  LoadOptions options;
  options.resolution = {25, 9, 5};
  LoadReport report;
  const VectorField f = loadField(path, options, &report);
  EXPECT_EQ(f.bounds().min, glm::vec3(0.0f));
  EXPECT_EQ(f.bounds().max, glm::vec3(3.0f, 2.0f, 1.0f));  // the wall block is left out
  EXPECT_TRUE(hasNote(report, "'wall'"));
  ASSERT_EQ(report.blocks.size(), 3u);
  EXPECT_NE(report.blocks[0].find("fluid: unstructured grid"), std::string::npos);
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 9; ++j)
      for (int i = 0; i < 25; ++i) {
        const glm::dvec3 p(f.pointPosition(i, j, k));
        const bool in = test::inL(p, 1e-6) || p.x >= 2.0 - 1e-6;
        ASSERT_EQ(f.valid(i, j, k), in) << p.x << " " << p.y << " " << p.z;
        if (in) {
          ASSERT_LE(glm::length(glm::dvec3(f.at(i, j, k)) - asymmetric(p)), kExact);
        }
      }
}

// A 2D velocity named in a multiblock must have the same components in every
// block that carries it: two in one block and three in another is refused,
// naming both counts, rather than read as planar in one part only.
TEST(MeshFormats, AVectorOfTwoComponentsInOneBlockAndThreeInAnotherIsRefused) {
  const auto dir = test::scratch();
  vtkNew<vtkMultiBlockDataSet> blocks;
  for (unsigned b = 0; b < 2; ++b) {
    vtkNew<vtkImageData> image;
    image->SetDimensions(2, 2, 2);
    image->SetOrigin(2.0 * b, 0.0, 0.0);
    vtkNew<vtkFloatArray> u;
    u->SetName("U");
    u->SetNumberOfComponents(b == 0 ? 2 : 3);
    u->SetNumberOfTuples(8);
    u->Fill(1.0f);
    image->GetPointData()->AddArray(u);
    blocks->SetBlock(b, image);
  }
  const auto path = dir / "mixed.vtm";
  vtkNew<vtkXMLMultiBlockDataWriter> w;
  w->SetInputData(blocks);
  w->SetFileName(path.c_str());
  ASSERT_EQ(w->Write(), 1);
  LoadOptions named;
  named.arrayName = "U";
  test::expectError([&] { loadField(path, named); },
                    {path.string(), "'U' has 2 components in one block and 3 in another"});
}

// Three one-component arrays (what many codes write) joined into a vector.
TEST(MeshFormats, ComponentsAreJoinedIntoAVector) {
  const auto dir = test::scratch();
  auto mesh = test::lMesh(2, asymmetric);
  vtkSmartPointer<vtkDataArray> velocity = mesh->GetPointData()->GetVectors();
  auto component = [&](const char* name, int c, double scale) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfTuples(mesh->GetNumberOfPoints());
    for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
      a->SetValue(p, scale * velocity->GetComponent(p, c));
    mesh->GetPointData()->AddArray(a);
  };
  component("u", 0, 1.0);
  component("v", 1, 1.0);
  component("w", 2, 1.0);
  mesh->GetPointData()->RemoveArray("velocity");
  const auto path = dir / "uvw.vtu";
  writeVtu(mesh, path, vtkXMLWriter::Appended);
  LoadOptions options;
  options.resolution = {9, 9, 5};

  LoadReport report;
  test::expectL(loadField(path, options, &report), asymmetric, kExact);  // found by itself
  EXPECT_TRUE(hasNote(report, "joined from the components 'u', 'v', 'w'"));
  EXPECT_EQ(report.arrayName, "velocity");

  options.arrayName = "w, v,u";  // as asked: z, y, x
  const VectorField swapped = loadField(path, options);
  const glm::vec3 at = swapped.at(2, 3, 1);
  const glm::dvec3 a = asymmetric(glm::dvec3(swapped.pointPosition(2, 3, 1)));
  EXPECT_NEAR(at.x, a.z, kExact);
  EXPECT_NEAR(at.z, a.x, kExact);

  options.arrayName = "u,v";  // two: a 2D simulation's, z 0
  const VectorField planar = loadField(path, options);
  const glm::vec3 uv = planar.at(2, 3, 1);
  const glm::dvec3 b = asymmetric(glm::dvec3(planar.pointPosition(2, 3, 1)));
  EXPECT_NEAR(uv.x, b.x, kExact);
  EXPECT_NEAR(uv.y, b.y, kExact);
  EXPECT_EQ(uv.z, 0.0f);
  options.arrayName = "u,v,w,q";
  test::expectError([&] { loadField(path, options); }, {path.string(), "three components"});
  {  // one component at the cells, two at the points: nothing to join
    auto split = vtkSmartPointer<vtkUnstructuredGrid>::New();
    split->DeepCopy(mesh);
    vtkNew<vtkDoubleArray> w;
    w->SetName("w");
    w->SetNumberOfTuples(split->GetNumberOfCells());
    w->Fill(1.0);
    split->GetPointData()->RemoveArray("w");
    split->GetCellData()->AddArray(w);
    const auto splitPath = dir / "split.vtu";
    writeVtu(split, splitPath, vtkXMLWriter::Appended);
    options.arrayName = "u,v,w";
    test::expectError([&] { loadField(splitPath, options); },
                      {splitPath.string(), "no block holds 'velocity' whole"});
  }
  options.arrayName = "u,v,q";
  test::expectError([&] { loadField(path, options); }, {path.string(), "'q'", "'u' (1 component)"});

  // Two sets of components: the user chooses.
  component("vel_x", 0, 2.0);
  component("vel_y", 1, 2.0);
  component("vel_z", 2, 2.0);
  writeVtu(mesh, path, vtkXMLWriter::Appended);
  options.arrayName.clear();
  test::expectError(
      [&] { loadField(path, options); },
      {path.string(), "several sets of components", "u,v,w", "vel_x,vel_y,vel_z", "--array u,v,w"});
  options.arrayName = "vel_x,vel_y,vel_z";
  report = {};
  const VectorField doubled = loadField(path, options, &report);
  EXPECT_EQ(report.arrayName, "vel");
  EXPECT_NEAR(doubled.at(2, 3, 1).y, 2.0 * asymmetric(glm::dvec3(doubled.pointPosition(2, 3, 1))).y,
              2 * kExact);
}

// Legacy files as VTK writes them: counted cell lists (up to version 4.2) and
// OFFSETS with CONNECTIVITY (5.1), ASCII and BINARY; polydata too.
TEST(MeshFormats, LegacyUnstructuredGridsAndPolyDataInEveryVersion) {
  const auto dir = test::scratch();
  const auto mesh = test::lMesh(4, asymmetric);
  LoadOptions options;
  options.resolution = {21, 21, 11};
  for (int version : {42, 51})
    for (bool binary : {false, true}) {
      SCOPED_TRACE(concat("version ", version, binary ? " binary" : " ascii"));
      const auto path = dir / concat("mesh", version, binary ? "b" : "a", ".vtk");
      vtkNew<vtkUnstructuredGridWriter> w;
      w->SetInputData(mesh);
      w->SetFileVersion(version);
      if (binary) w->SetFileTypeToBinary();
      w->SetFileName(path.c_str());
      ASSERT_EQ(w->Write(), 1);
      LoadReport report;
      test::expectL(loadField(path, options, &report), asymmetric, kExact);
      EXPECT_EQ(report.cells, std::uint64_t(mesh->GetNumberOfCells()));
    }
  // Polydata: a sheet of triangles at z = 0.75 (VTK's geometry filter, which
  // would make a surface of the mesh, leaks in 9.1).
  const auto sheet = triangleSheet(4, 0.0, 0.0, 0.5, 0.5, 0.75);
  const auto path = dir / "sheet.vtk";
  vtkNew<vtkPolyDataWriter> w;
  w->SetInputData(sheet);
  w->SetFileName(path.c_str());
  ASSERT_EQ(w->Write(), 1);
  LoadOptions flat;
  flat.resolution = {9, 9, 1};
  LoadReport report;
  const VectorField f = loadField(path, flat, &report);
  EXPECT_EQ(report.cells, std::uint64_t(32));
  EXPECT_EQ(f.invalidCount(), 0u);
  for (int j = 0; j < 9; ++j)
    for (int i = 0; i < 9; ++i)
      ASSERT_LE(
          glm::length(glm::dvec3(f.at(i, j, 0)) - asymmetric(glm::dvec3(f.pointPosition(i, j, 0)))),
          kExact);
}

// A .pvd of meshes is a time series like any other: every frame on the
// first frame's grid.
TEST(MeshFormats, APvdOfMeshesIsATimeSeries) {
  const auto dir = test::scratch();
  const auto doubled = [](const glm::dvec3& p) { return 2.0 * asymmetric(p); };
  writeVtu(test::lMesh(4, asymmetric), dir / "t0.vtu", vtkXMLWriter::Appended);
  writeVtu(test::lMesh(4, doubled), dir / "t1.vtu", vtkXMLWriter::Appended);
  test::writeText(dir / "run.pvd",
                  "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
                  "<Collection>\n<DataSet timestep=\"0\" file=\"t0.vtu\"/>\n"
                  "<DataSet timestep=\"2.5\" file=\"t1.vtu\"/>\n</Collection>\n</VTKFile>\n");
  const FieldSequence sequence = FieldSequence::fromFile(dir / "run.pvd");
  ASSERT_EQ(sequence.size(), 2u);
  EXPECT_EQ(sequence.time(1), 2.5);
  test::expectL(sequence.frame(0), asymmetric, kExact);
  test::expectL(sequence.frame(1), doubled, 2 * kExact);
}

// Vectors at scattered points (a particle tracker's output), as vertices of
// polydata: each grid point the Shepard mean of the points within twice
// their spacing, so within the field's stretch (3) times that radius of it.
TEST(MeshFormats, ScatteredPointsAreInterpolatedBetween) {
  const auto dir = test::scratch();
  vtkNew<vtkPolyData> cloud;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  std::uint32_t state = 12345u;
  auto uniform = [&] {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 24);
  };
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 p(2.0 * uniform(), uniform(), uniform());
    const vtkIdType id = points->InsertNextPoint(p.x, p.y, p.z);
    vertices->InsertNextCell(1, &id);
    const glm::dvec3 a = asymmetric(p);
    v->InsertNextTuple3(a.x, a.y, a.z);
  }
  cloud->SetPoints(points);
  cloud->SetVerts(vertices);
  cloud->GetPointData()->SetVectors(v);
  const auto path = dir / "tracks.vtp";
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetInputData(cloud);
  w->SetFileName(path.c_str());
  ASSERT_EQ(w->Write(), 1);
  LoadReport report;
  LoadOptions options;
  options.resolution = {21, 11, 11};
  const VectorField f = loadField(path, options, &report);
  ASSERT_TRUE(hasNote(report, "points without cells"));
  double radius = 0.0;
  for (const std::string& note : report.notes)
    if (const auto at = note.find("within "); at != std::string::npos)
      radius = std::stod(note.substr(at + 7));
  ASSERT_GT(radius, 0.0);
  EXPECT_NEAR(radius, 2.0 * std::cbrt(2.0 / n), 0.1 * radius);
  std::size_t valid = 0;
  for (int k = 0; k < 11; ++k)
    for (int j = 0; j < 11; ++j)
      for (int i = 0; i < 21; ++i) {
        if (!f.valid(i, j, k)) continue;
        ++valid;
        const glm::dvec3 p(f.pointPosition(i, j, k));
        ASSERT_LE(glm::length(glm::dvec3(f.at(i, j, k)) - asymmetric(p)), 3.0 * radius + kExact);
      }
  EXPECT_GT(valid, std::size_t(0.95 * 21 * 11 * 11));
}

}  // namespace
}  // namespace sandstorm
