// The mesh resampler against VTK's vtkProbeFilter (what ParaView's Resample To
// Image runs), on jittered meshes of tetrahedra and hexahedra (the resampler's
// inline paths) and wedges (VTK's own cells), a curvilinear structured grid and
// a stretched rectilinear one (inline too), carrying a curved flow.
//
// The two agree on which points lie in the mesh, and on every value to float
// rounding, but where a point lies within VTK's tolerance (a thousandth of a
// cell, parametrically) outside one cell and inside its neighbour: VTK takes
// whichever cell its locator meets first and extrapolates, the resampler
// takes the cell the point is inside. There each must equal its own cell's
// interpolation, which the test computes by visiting every cell.
#include <gtest/gtest.h>

#include <cmath>

#include <vtkDoubleArray.h>
#include <vtkGenericCell.h>
#include <vtkImageData.h>
#include <vtkProbeFilter.h>
#include <vtkRectilinearGrid.h>
#include <vtkStaticCellLocator.h>
#include <vtkStructuredGrid.h>

#include "core/io/mesh_resampler.h"
#include "tests/io/io_test_util.h"
#include "tests/io/mesh_test_util.h"

namespace sandstorm {
namespace {

glm::dvec3 curved(const glm::dvec3& p) {
  return {-std::sin(2.0 * p.y) + 0.3 * p.z, std::sin(2.0 * p.x) * std::cos(p.z),
          0.5 + 0.2 * p.x * p.y};
}

void addFlow(vtkDataSet* mesh) {
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p) {
    double x[3];
    mesh->GetPoint(p, x);
    const glm::dvec3 f = curved({x[0], x[1], x[2]});
    v->SetTuple3(p, f.x, f.y, f.z);
  }
  mesh->GetPointData()->SetVectors(v);
}

// n^3 jittered hexahedra over [0, 1]^3, or each split in two wedges.
vtkSmartPointer<vtkUnstructuredGrid> boxMesh(int n, bool wedges) {
  vtkNew<vtkPoints> points;
  auto id = [&](int i, int j, int k) { return vtkIdType(i + (n + 1) * (j + (n + 1) * k)); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const bool inner = i > 0 && i < n && j > 0 && j < n && k > 0 && k < n;
        const double wobble = inner ? 0.08 / n * std::sin(double(7 * i + 13 * j + 29 * k)) : 0.0;
        points->InsertNextPoint(double(i) / n + wobble, double(j) / n - wobble,
                                double(k) / n + 0.5 * wobble);
      }
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  mesh->SetPoints(points);
  mesh->Allocate();
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const vtkIdType a = id(i, j, k), b = id(i + 1, j, k), c = id(i + 1, j + 1, k),
                        d = id(i, j + 1, k), e = id(i, j, k + 1), f = id(i + 1, j, k + 1),
                        g = id(i + 1, j + 1, k + 1), h = id(i, j + 1, k + 1);
        if (wedges) {
          const vtkIdType w1[6] = {a, b, c, e, f, g}, w2[6] = {a, c, d, e, g, h};
          mesh->InsertNextCell(VTK_WEDGE, 6, w1);
          mesh->InsertNextCell(VTK_WEDGE, 6, w2);
        } else {
          const vtkIdType hex[8] = {a, b, c, d, e, f, g, h};
          mesh->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
        }
      }
  addFlow(mesh);
  return mesh;
}

// n^3 warped hexahedra of a structured grid over about [0, 1]^3.
vtkSmartPointer<vtkStructuredGrid> curvilinearGrid(int n) {
  vtkNew<vtkPoints> points;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double u = double(i) / n, v = double(j) / n, w = double(k) / n;
        points->InsertNextPoint(u + 0.15 * w + 0.04 * std::sin(6.0 * v), v + 0.05 * u * w,
                                w * (1.0 + 0.2 * u) + 0.03 * std::sin(5.0 * u + 3.0 * v));
      }
  auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
  grid->SetDimensions(n + 1, n + 1, n + 1);
  grid->SetPoints(points);
  addFlow(grid);
  return grid;
}

// A rectilinear grid over [0, 1]^3: stretched along x and z, even along y
// (where its coordinates fall on the resampling grid's points).
vtkSmartPointer<vtkRectilinearGrid> stretchedGrid(int n) {
  auto grid = vtkSmartPointer<vtkRectilinearGrid>::New();
  grid->SetDimensions(n + 1, n + 1, n + 1);
  vtkNew<vtkDoubleArray> axes[3];
  for (int i = 0; i <= n; ++i) {
    const double u = double(i) / n;
    axes[0]->InsertNextValue(u * u);
    axes[1]->InsertNextValue(u);
    axes[2]->InsertNextValue(u + 0.3 * u * (1.0 - u));
  }
  grid->SetXCoordinates(axes[0]);
  grid->SetYCoordinates(axes[1]);
  grid->SetZCoordinates(axes[2]);
  addFlow(grid);
  return grid;
}

// Every cell that holds x by VTK's rule, with its interpolated flow and how
// far outside it x lies, parametrically.
struct Holder {
  glm::dvec3 value;
  double outside;
};
std::vector<Holder> holders(vtkDataSet* mesh, const double x[3]) {
  std::vector<Holder> out;
  vtkNew<vtkGenericCell> cell;
  vtkDataArray* v = mesh->GetPointData()->GetVectors();
  double closest[3], pcoords[3], dist2, weights[8];
  int sub;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c) {
    mesh->GetCell(c, cell);
    if (cell->EvaluatePosition(x, closest, sub, pcoords, dist2, weights) != 1) continue;
    glm::dvec3 value(0.0);
    for (vtkIdType i = 0; i < cell->GetNumberOfPoints(); ++i)
      for (int k = 0; k < 3; ++k)
        value[k] += weights[i] * v->GetComponent(cell->GetPointId(i), k);
    // vtkGenericCell does not forward GetParametricDistance: ask the cell it holds.
    out.push_back({value, cell->GetRepresentativeCell()->GetParametricDistance(pcoords)});
  }
  return out;
}

void compareWithProbe(vtkDataSet* mesh, const glm::ivec3& dims) {
  double b[6];
  mesh->GetBounds(b);
  UniformGrid grid;
  grid.dims = dims;
  for (int a = 0; a < 3; ++a) {
    grid.origin[a] = b[2 * a];
    grid.spacing[a] = (b[2 * a + 1] - b[2 * a]) / (dims[a] - 1);
  }
  const MeshSource source{mesh, {mesh->GetPointData()->GetVectors()}};
  const ResampledArrays ours = resampleMeshes({&source, 1}, grid, "test");

  vtkNew<vtkImageData> image;
  image->SetDimensions(dims.x, dims.y, dims.z);
  image->SetOrigin(grid.origin.x, grid.origin.y, grid.origin.z);
  image->SetSpacing(grid.spacing.x, grid.spacing.y, grid.spacing.z);
  vtkNew<vtkStaticCellLocator> locator;
  vtkNew<vtkProbeFilter> probe;
  probe->SetInputData(image);
  probe->SetSourceData(mesh);
  probe->SetCellLocatorPrototype(locator);
  probe->Update();
  vtkDataSet* probed = probe->GetOutput();
  vtkDataArray* theirs = probed->GetPointData()->GetArray("velocity");
  vtkDataArray* mask = probed->GetPointData()->GetArray(probe->GetValidPointMaskArrayName());
  ASSERT_TRUE(theirs && mask);

  constexpr double kRounding = 1e-6;  // float rounding of values up to ~1.5
  std::size_t valid = 0, elsewhere = 0;
  for (vtkIdType p = 0; p < probed->GetNumberOfPoints(); ++p) {
    double x[3];
    probed->GetPoint(p, x);
    const bool in = mask->GetComponent(p, 0) != 0.0;
    ASSERT_EQ(ours.valid[std::size_t(p)] != 0, in) << "at " << x[0] << " " << x[1] << " " << x[2];
    if (!in) continue;
    ++valid;
    const glm::dvec3 vtk(theirs->GetComponent(p, 0), theirs->GetComponent(p, 1),
                         theirs->GetComponent(p, 2));
    const float* o = &ours.values[0][3 * std::size_t(p)];
    const glm::dvec3 mine(o[0], o[1], o[2]);
    if (glm::length(mine - vtk) <= kRounding) continue;
    // Two cells hold the point: each side's value is its own cell's, and ours
    // is the one the point lies deepest in.
    ++elsewhere;
    const std::vector<Holder> cells = holders(mesh, x);
    ASSERT_GE(cells.size(), 2u) << "at " << x[0] << " " << x[1] << " " << x[2];
    const auto deepest =
        std::min_element(cells.begin(), cells.end(),
                         [](const Holder& a, const Holder& b) { return a.outside < b.outside; });
    EXPECT_LE(glm::length(mine - deepest->value), kRounding);
    EXPECT_TRUE(std::any_of(cells.begin(), cells.end(), [&](const Holder& h) {
      return glm::length(vtk - h.value) <= kRounding;
    }));
  }
  EXPECT_GT(valid, std::size_t(0));
  std::cout << "[ measured ] " << valid << " points in the mesh; " << elsewhere
            << " within VTK's tolerance of a neighbouring cell, which VTK extrapolated\n";
}

TEST(MeshResampler, TetrahedraAgreeWithVtkProbeFilter) {
  test::scratch();
  compareWithProbe(test::lMesh(5, curved), {41, 41, 21});
}

TEST(MeshResampler, HexahedraAgreeWithVtkProbeFilter) {
  test::scratch();
  compareWithProbe(boxMesh(6, false), {31, 31, 31});
}

TEST(MeshResampler, WedgesAgreeWithVtkProbeFilter) {
  test::scratch();
  compareWithProbe(boxMesh(5, true), {26, 26, 26});
}

TEST(MeshResampler, StructuredGridsAgreeWithVtkProbeFilter) {
  test::scratch();
  const auto grid = curvilinearGrid(9);
  compareWithProbe(grid, {33, 29, 31});
  // Points marked as another piece's (a parallel file's shared layer) change
  // nothing; a hidden point empties the cells around it, as in VTK.
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
    ghosts->SetValue(p, p % 10 < 3 ? vtkDataSetAttributes::DUPLICATEPOINT : 0);
  grid->GetPointData()->AddArray(ghosts);
  compareWithProbe(grid, {33, 29, 31});
  ghosts->SetValue(5 + 10 * (5 + 10 * 5), vtkDataSetAttributes::HIDDENPOINT);
  grid->Modified();
  compareWithProbe(grid, {33, 29, 31});
}

TEST(MeshResampler, RectilinearGridsAgreeWithVtkProbeFilter) {
  test::scratch();
  compareWithProbe(stretchedGrid(8), {27, 33, 25});
}

// The same grid however many threads the machine has and however they are
// timed: the cells are visited in order within each slab.
TEST(MeshResampler, GhostCellsAreSkippedAndTheResultIsRepeatable) {
  test::scratch();
  auto mesh = test::lMesh(4, curved);
  UniformGrid grid;
  grid.dims = {17, 17, 9};
  grid.spacing = glm::dvec3(2.0 / 16, 2.0 / 16, 1.0 / 8);
  const MeshSource source{mesh, {mesh->GetPointData()->GetVectors()}};
  const ResampledArrays first = resampleMeshes({&source, 1}, grid, "test");
  for (int run = 0; run < 3; ++run) {
    const ResampledArrays again = resampleMeshes({&source, 1}, grid, "test");
    ASSERT_EQ(again.values[0], first.values[0]);
    ASSERT_EQ(again.valid, first.valid);
  }
  // Every cell of the L's upper half a ghost: that half is outside.
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfTuples(mesh->GetNumberOfCells());
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c) {
    double box[6];
    mesh->GetCellBounds(c, box);
    ghosts->SetValue(c, box[4] + box[5] > 1.0 ? vtkDataSetAttributes::DUPLICATECELL : 0);
  }
  mesh->GetCellData()->AddArray(ghosts);
  const ResampledArrays lower = resampleMeshes({&source, 1}, grid, "test");
  for (int k = 0; k < 9; ++k) {
    if (k == 4) continue;  // z = 0.5: on the halves' jittered seam
    const std::size_t p = std::size_t(3 + 17 * (3 + 17 * k));  // x = y = 0.375, inside the L
    EXPECT_EQ(lower.valid[p] != 0, k < 4) << "z = " << k / 8.0;
    EXPECT_EQ(first.valid[p], 1);
  }
}

}  // namespace
}  // namespace sandstorm
