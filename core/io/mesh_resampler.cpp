#include "core/io/mesh_resampler.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetAttributes.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRectilinearGrid.h>
#include <vtkStructuredGrid.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include "core/io/hexahedron_inverse.h"
#include "core/util/error.h"
#include "core/util/parallel_for.h"
#include "core/util/progress_meter.h"

namespace sandstorm {
namespace {

// VTK's cells accept a point whose parametric coordinates lie this far
// outside them (vtkTetra::EvaluatePosition and the others).
constexpr double kParametricTolerance = 0.001;
// A 2D or 1D cell holds points this close to it, in units of its diagonal
// (vtkProbeFilter's tolerance: a thousandth of a cell's length).
constexpr double kSurfaceTolerance = 0.001;
constexpr float kNone = std::numeric_limits<float>::infinity();

// One array's point values, read without a virtual call where the array is
// VTK's plain float or double array.
struct ArrayView {
  vtkDataArray* array = nullptr;
  const float* floats = nullptr;
  const double* doubles = nullptr;
  int components = 0;
  double at(vtkIdType point, int c) const {
    const vtkIdType i = point * components + c;
    if (floats) return double(floats[i]);
    if (doubles) return doubles[i];
    return array->GetComponent(point, c);
  }
};

// How a source's cells are looked at: through VTK's cells, or inline.
enum class Cells {
  Any,           // vtkDataSet::GetCell and the cell's EvaluatePosition
  Unstructured,  // an unstructured grid: its tetrahedra and hexahedra inline
  Structured,    // a 3D structured grid: hexahedra, their points from (i, j, k)
  Rectilinear,   // a 3D rectilinear grid: voxels from the axes' coordinates
};

struct Source {
  vtkDataSet* data = nullptr;
  Cells cells = Cells::Any;
  glm::ivec3 pointDims{0};      // Structured, Rectilinear
  std::vector<double> axes[3];  // Rectilinear: each axis's coordinates
  vtkUnsignedCharArray* ghosts = nullptr;
  std::vector<ArrayView> arrays;
  std::uint64_t firstCell = 0;  // of all sources' cells together
  // An unstructured grid's connectivity and points, read in place.
  const vtkTypeInt64* offsets64 = nullptr;
  const vtkTypeInt64* connectivity64 = nullptr;
  const vtkTypeInt32* offsets32 = nullptr;
  const vtkTypeInt32* connectivity32 = nullptr;
  const float* pointsF = nullptr;
  const double* pointsD = nullptr;
};

// What one thread needs to look at cells.
struct Workspace {
  vtkNew<vtkGenericCell> cell;
  vtkNew<vtkIdList> list;
  std::vector<vtkIdType> ids;   // the cell's points
  std::vector<double> corners;  // their coordinates, x y z each
  std::vector<double> weights;
};

bool isGhost(const Source& s, vtkIdType cell) {
  if (!s.ghosts) return false;
  const unsigned char g = s.ghosts->GetValue(cell);
  return (g & (vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL)) != 0;
}

// A structured grid's cell (i, j, k): its corner (i, j, k) and the points
// after it in vtkStructuredGrid::GetCell's order, bottom face then top.
// (Fewer than 2^32 cells: 32-bit division, the faster.)
glm::ivec3 cellIndex(const Source& s, vtkIdType cell) {
  const auto c = std::uint32_t(cell), nx = std::uint32_t(s.pointDims.x - 1),
             ny = std::uint32_t(s.pointDims.y - 1);
  const std::uint32_t row = c / nx;
  return {int(c - row * nx), int(row % ny), int(row / ny)};
}

void structuredIds(const Source& s, vtkIdType cell, std::vector<vtkIdType>& ids) {
  const glm::ivec3 c = cellIndex(s, cell);
  const vtkIdType row = s.pointDims.x, layer = vtkIdType(s.pointDims.x) * s.pointDims.y;
  const vtkIdType p = c.x + row * c.y + layer * c.z;
  ids.assign({p, p + 1, p + 1 + row, p + row, p + layer, p + layer + 1, p + layer + 1 + row,
              p + layer + row});
}

// A rectilinear grid's voxel: points in vtkVoxel's order (x fastest, then y,
// then z), corners from the axes' coordinates.
bool voxelBounds(const Source& s, vtkIdType cell, Workspace& w, glm::dvec3& lo, glm::dvec3& hi) {
  const glm::ivec3 c = cellIndex(s, cell);
  const vtkIdType row = s.pointDims.x, layer = vtkIdType(s.pointDims.x) * s.pointDims.y;
  const vtkIdType p = c.x + row * c.y + layer * c.z;
  w.ids.resize(8);
  w.corners.resize(24);
  for (int n = 0; n < 8; ++n) {
    const glm::ivec3 o(n & 1, (n >> 1) & 1, n >> 2);
    w.ids[std::size_t(n)] = p + o.x + row * o.y + layer * o.z;
    for (int a = 0; a < 3; ++a)
      w.corners[std::size_t(3 * n + a)] = s.axes[a][std::size_t(c[a] + o[a])];
  }
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::min(w.corners[std::size_t(a)], w.corners[std::size_t(21 + a)]);
    hi[a] = std::max(w.corners[std::size_t(a)], w.corners[std::size_t(21 + a)]);
  }
  return true;
}

// The cell's points (ids into w.ids, coordinates into w.corners) and its box.
// False for a cell without points.
bool cellBounds(const Source& s, vtkIdType cell, Workspace& w, glm::dvec3& lo, glm::dvec3& hi) {
  if (s.cells == Cells::Rectilinear) return voxelBounds(s, cell, w, lo, hi);
  if (s.cells == Cells::Structured) {
    structuredIds(s, cell, w.ids);
  } else if (s.offsets64) {
    w.ids.assign(s.connectivity64 + s.offsets64[cell], s.connectivity64 + s.offsets64[cell + 1]);
  } else if (s.offsets32) {
    w.ids.assign(s.connectivity32 + s.offsets32[cell], s.connectivity32 + s.offsets32[cell + 1]);
  } else {
    s.data->GetCellPoints(cell, w.list);
    w.ids.assign(w.list->begin(), w.list->end());
  }
  const std::size_t n = w.ids.size();
  if (n == 0) return false;
  w.corners.resize(3 * n);
  lo = glm::dvec3(std::numeric_limits<double>::max());
  hi = -lo;
  for (std::size_t i = 0; i < n; ++i) {
    double* x = &w.corners[3 * i];
    const std::size_t p = 3 * std::size_t(w.ids[i]);
    if (s.pointsF) {
      x[0] = double(s.pointsF[p]), x[1] = double(s.pointsF[p + 1]), x[2] = double(s.pointsF[p + 2]);
    } else if (s.pointsD) {
      x[0] = s.pointsD[p], x[1] = s.pointsD[p + 1], x[2] = s.pointsD[p + 2];
    } else {
      s.data->GetPoint(w.ids[i], x);
    }
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], x[a]);
      hi[a] = std::max(hi[a], x[a]);
    }
  }
  return true;
}

struct IndexBox {
  glm::ivec3 lo, hi;  // inclusive; empty when any hi < lo
  bool empty() const { return hi.x < lo.x || hi.y < lo.y || hi.z < lo.z; }
};

// The grid points within the cell's box widened by what its tolerance admits.
IndexBox indexBox(const UniformGrid& g, const glm::dvec3& lo, const glm::dvec3& hi) {
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(lo[a]) || !std::isfinite(hi[a]))
      return {glm::ivec3(0), glm::ivec3(-1)};  // a cell at no finite place holds no point
  const double margin =
      1.1 * std::max(kParametricTolerance, kSurfaceTolerance) * glm::length(hi - lo);
  IndexBox box;
  for (int a = 0; a < 3; ++a) {
    const double from = lo[a] - margin - g.origin[a], to = hi[a] + margin - g.origin[a];
    if (g.dims[a] == 1 || g.spacing[a] == 0.0) {
      const bool in = from <= 0.0 && to >= 0.0;
      box.lo[a] = 0;
      box.hi[a] = in ? 0 : -1;
      continue;
    }
    const double first = std::ceil(from / g.spacing[a]), last = std::floor(to / g.spacing[a]);
    box.lo[a] = int(std::clamp(first, 0.0, double(g.dims[a])));
    box.hi[a] = int(std::clamp(last, -1.0, double(g.dims[a] - 1)));
  }
  return box;
}

// vtkCell::GetParametricDistance: how far outside the unit cube, at most.
double parametricDistance(const double p[3]) {
  double most = 0.0;
  for (int a = 0; a < 3; ++a)
    most = std::max(most, p[a] < 0.0 ? -p[a] : (p[a] > 1.0 ? p[a] - 1.0 : 0.0));
  return most;
}

// Whether a structured grid blanks points (vtkGhostType's hidden bit: the
// cells around them are empty). Points another piece owns (the duplicate
// bit, as a parallel file's pieces mark their shared layers) blank nothing.
bool hidesPoints(vtkStructuredGrid* grid) {
  vtkDataArray* array = grid->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName());
  if (!array) return false;
  auto* ghosts = vtkUnsignedCharArray::SafeDownCast(array);
  if (!ghosts || ghosts->GetNumberOfTuples() != grid->GetNumberOfPoints()) return true;
  const unsigned char* g = ghosts->GetPointer(0);
  return std::any_of(g, g + ghosts->GetNumberOfTuples(),
                     [](unsigned char v) { return (v & vtkDataSetAttributes::HIDDENPOINT) != 0; });
}

// Which cells of `data` are looked at inline; a structured or rectilinear
// grid's dimensions (and a rectilinear one's coordinates) into `s`. Grids
// flat along an axis (quads, pixels) and structured grids with hidden
// points go through VTK's cells.
Cells inlineCells(vtkDataSet* data, Source& s) {
  if (vtkUnstructuredGrid::SafeDownCast(data)) return Cells::Unstructured;
  int d[3] = {0, 0, 0};
  if (auto* grid = vtkStructuredGrid::SafeDownCast(data)) {
    grid->GetDimensions(d);
    if (d[0] < 2 || d[1] < 2 || d[2] < 2 || !grid->GetPoints() || hidesPoints(grid))
      return Cells::Any;
    s.pointDims = {d[0], d[1], d[2]};
    return Cells::Structured;
  }
  if (auto* grid = vtkRectilinearGrid::SafeDownCast(data)) {
    grid->GetDimensions(d);
    vtkDataArray* axes[3] = {grid->GetXCoordinates(), grid->GetYCoordinates(),
                             grid->GetZCoordinates()};
    for (int a = 0; a < 3; ++a)
      if (d[a] < 2 || !axes[a] || axes[a]->GetNumberOfTuples() != d[a]) return Cells::Any;
    s.pointDims = {d[0], d[1], d[2]};
    for (int a = 0; a < 3; ++a)
      for (vtkIdType i = 0; i < d[a]; ++i)
        s.axes[a].push_back(axes[a]->GetComponent(i, 0));
    return Cells::Rectilinear;
  }
  return Cells::Any;
}

class Resampler {
 public:
  Resampler(std::span<const MeshSource> sources, const UniformGrid& grid) : grid_(grid) {
    for (const MeshSource& m : sources) {
      Source s;
      s.data = m.data;
      s.firstCell = cells_;
      cells_ += std::uint64_t(m.data->GetNumberOfCells());
      // Lazily built structures are built here, once, before threads read them.
      if (auto* poly = vtkPolyData::SafeDownCast(m.data); poly && poly->NeedToBuildCells())
        poly->BuildCells();
      if (m.data->GetNumberOfCells() > 0) m.data->GetCell(0, workspace_.cell);
      m.data->ComputeBounds();
      s.cells = inlineCells(m.data, s);
      if (auto* grid = vtkUnstructuredGrid::SafeDownCast(m.data)) {
        if (vtkCellArray* cells = grid->GetCells(); cells && cells->GetNumberOfCells() > 0) {
          if (cells->IsStorage64Bit()) {
            s.offsets64 = cells->GetOffsetsArray64()->GetPointer(0);
            s.connectivity64 = cells->GetConnectivityArray64()->GetPointer(0);
          } else {
            s.offsets32 = cells->GetOffsetsArray32()->GetPointer(0);
            s.connectivity32 = cells->GetConnectivityArray32()->GetPointer(0);
          }
        }
      }
      if (auto* set = vtkPointSet::SafeDownCast(m.data); set && set->GetPoints()) {
        vtkDataArray* xyz = set->GetPoints()->GetData();
        if (auto* f = vtkFloatArray::SafeDownCast(xyz)) s.pointsF = f->GetPointer(0);
        if (auto* d = vtkDoubleArray::SafeDownCast(xyz)) s.pointsD = d->GetPointer(0);
      }
      s.ghosts = vtkUnsignedCharArray::SafeDownCast(
          m.data->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
      if (s.ghosts && s.ghosts->GetNumberOfTuples() != m.data->GetNumberOfCells())
        s.ghosts = nullptr;
      maxCellSize_ = std::max(maxCellSize_, m.data->GetMaxCellSize());
      if (sources_.empty()) {
        for (vtkDataArray* a : m.arrays)
          components_.push_back(a->GetNumberOfComponents());
      } else if (m.arrays.size() != components_.size()) {
        throw Error("the blocks carry different numbers of arrays to resample");
      }
      for (std::size_t i = 0; i < m.arrays.size(); ++i) {
        vtkDataArray* a = m.arrays[i];
        if (a->GetNumberOfComponents() != components_[i] ||
            a->GetNumberOfTuples() != m.data->GetNumberOfPoints())
          throw Error(concat("array '", a->GetName() ? a->GetName() : "", "' has ",
                             a->GetNumberOfComponents(), " components x ", a->GetNumberOfTuples(),
                             " tuples; expected ", components_[i], " x ",
                             m.data->GetNumberOfPoints(), " (one per point)"));
        ArrayView v;
        v.array = a;
        v.components = a->GetNumberOfComponents();
        if (auto* f = vtkFloatArray::SafeDownCast(a)) v.floats = f->GetPointer(0);
        if (auto* d = vtkDoubleArray::SafeDownCast(a)) v.doubles = d->GetPointer(0);
        s.arrays.push_back(v);
      }
      sources_.push_back(std::move(s));
    }
    if (cells_ >= (std::uint64_t{1} << 32))
      throw Error(concat(cells_, " cells: more than the 2^32 that can be resampled at once"));
    axis_ = 0;
    for (int a = 1; a < 3; ++a)
      if (grid_.dims[a] > grid_.dims[axis_]) axis_ = a;
  }

  ResampledArrays run(const std::string& what) {
    ResampledArrays out;
    const std::size_t points = grid_.points();
    out.values.resize(components_.size());
    for (std::size_t i = 0; i < components_.size(); ++i)
      out.values[i].assign(points * std::size_t(components_[i]), 0.0f);
    best_.assign(points, kNone);
    values_ = &out.values;

    ParallelFor pool;
    bin(pool);
    ProgressMeter progress(what, entries_.size(), "cell visits");
    std::atomic<std::size_t> nextSlab{0};
    pool.run(pool.threads(), [&](std::size_t, std::size_t) {
      Workspace w;
      w.weights.resize(std::size_t(std::max(maxCellSize_, 4)));
      for (std::size_t s; (s = nextSlab.fetch_add(1)) < slabs_;) {
        for (std::size_t e = slabStart_[s]; e < slabStart_[s + 1]; ++e)
          visit(entries_[e], int(s), w);
        progress.add(slabStart_[s + 1] - slabStart_[s]);
      }
    });
    progress.finish();

    out.valid.resize(points);
    for (std::size_t p = 0; p < points; ++p) {
      out.valid[p] = best_[p] != kNone ? 1 : 0;
      out.validCount += out.valid[p];
    }
    return out;
  }

 private:
  // The source holding cell `global`: the last whose first cell is at or
  // before it (a search: a parallel file may have thousands of pieces).
  const Source& sourceOf(std::uint64_t global) const {
    const auto after =
        std::upper_bound(sources_.begin(), sources_.end(), global,
                         [](std::uint64_t g, const Source& s) { return g < s.firstCell; });
    return *(after - 1);
  }

  // Each cell's range of slabs, then the cells of each slab in order.
  void bin(ParallelFor& pool) {
    const int n = grid_.dims[axis_];
    slabs_ = std::size_t(std::clamp(n, 1, int(pool.threads()) * 16));
    slabOf_.resize(std::size_t(n));
    slabBegin_.assign(slabs_ + 1, 0);
    for (std::size_t s = 0; s <= slabs_; ++s)
      slabBegin_[s] = int(std::uint64_t(n) * s / slabs_);
    for (std::size_t s = 0; s < slabs_; ++s)
      for (int i = slabBegin_[s]; i < slabBegin_[s + 1]; ++i)
        slabOf_[std::size_t(i)] = int(s);

    std::vector<std::int32_t> first(cells_, 0), last(cells_, -1);
    pool.run(cells_, [&](std::size_t begin, std::size_t end) {
      Workspace w;
      for (std::size_t g = begin; g < end; ++g) {
        const Source& s = sourceOf(g);
        const vtkIdType cell = vtkIdType(g - s.firstCell);
        glm::dvec3 lo, hi;
        if (isGhost(s, cell) || !cellBounds(s, cell, w, lo, hi)) continue;
        const IndexBox box = indexBox(grid_, lo, hi);
        if (box.empty()) continue;
        first[g] = slabOf_[std::size_t(box.lo[axis_])];
        last[g] = slabOf_[std::size_t(box.hi[axis_])];
      }
    });
    std::vector<std::size_t> count(slabs_ + 1, 0);
    for (std::uint64_t g = 0; g < cells_; ++g)
      for (std::int32_t s = first[g]; s <= last[g]; ++s)
        ++count[std::size_t(s) + 1];
    slabStart_.assign(slabs_ + 1, 0);
    for (std::size_t s = 0; s < slabs_; ++s)
      slabStart_[s + 1] = slabStart_[s] + count[s + 1];
    entries_.resize(slabStart_[slabs_]);
    std::vector<std::size_t> at(slabStart_.begin(), slabStart_.end() - 1);
    for (std::uint64_t g = 0; g < cells_; ++g)
      for (std::int32_t s = first[g]; s <= last[g]; ++s)
        entries_[at[std::size_t(s)]++] = std::uint32_t(g);
  }

  // The grid points of one cell within one slab.
  void visit(std::uint32_t global, int slab, Workspace& w) {
    const Source& s = sourceOf(global);
    const vtkIdType cell = vtkIdType(global - s.firstCell);
    glm::dvec3 lo, hi;
    if (!cellBounds(s, cell, w, lo, hi)) return;
    IndexBox box = indexBox(grid_, lo, hi);
    box.lo[axis_] = std::max(box.lo[axis_], slabBegin_[std::size_t(slab)]);
    box.hi[axis_] = std::min(box.hi[axis_], slabBegin_[std::size_t(slab) + 1] - 1);
    if (box.empty()) return;
    if (s.cells == Cells::Rectilinear) {
      visitVoxel(s, box, w);
      return;
    }
    if (s.cells == Cells::Structured) {
      visitHexahedron(s, box, w);
      return;
    }
    const int type = s.data->GetCellType(cell);
    if (s.cells == Cells::Unstructured && type == VTK_TETRA && w.ids.size() == 4) {
      visitTetra(s, box, w);
      return;
    }
    if (s.cells == Cells::Unstructured && type == VTK_HEXAHEDRON && w.ids.size() == 8) {
      visitHexahedron(s, box, w);
      return;
    }
    s.data->GetCell(cell, w.cell);
    const int dimension = w.cell->GetCellDimension();
    const double diagonal = glm::length(hi - lo);
    const double tolerance2 = std::pow(kSurfaceTolerance * diagonal, 2.0);
    double closest[3], pcoords[3], dist2 = 0.0;
    int subId = 0;
    forEachPoint(box, [&](const double x[3], std::size_t index) {
      const int inside =
          w.cell->EvaluatePosition(x, closest, subId, pcoords, dist2, w.weights.data());
      if (inside != 1) return;
      // vtkGenericCell does not forward this one: ask the cell it holds.
      double badness = w.cell->GetRepresentativeCell()->GetParametricDistance(pcoords);
      if (dimension < 3) {
        if (dist2 > tolerance2) return;
        badness += diagonal > 0.0 ? std::sqrt(dist2) / diagonal : 0.0;
      }
      if (badness < double(best_[index]))
        write(s, index, float(badness), w.cell->GetPointIds()->GetPointer(0),
              std::size_t(w.cell->GetNumberOfPoints()), w.weights);
    });
  }

  // vtkTetra::EvaluatePosition's arithmetic, without building a vtkTetra.
  void visitTetra(const Source& s, const IndexBox& box, Workspace& w) {
    const double* p0 = &w.corners[0];
    double c1[3], c2[3], c3[3];
    for (int i = 0; i < 3; ++i) {
      c1[i] = w.corners[3 + std::size_t(i)] - p0[i];
      c2[i] = w.corners[6 + std::size_t(i)] - p0[i];
      c3[i] = w.corners[9 + std::size_t(i)] - p0[i];
    }
    const double det = vtkMath::Determinant3x3(c1, c2, c3);
    if (det == 0.0) return;
    constexpr double lo = -kParametricTolerance, hi = 1.0 + kParametricTolerance;
    forEachPoint(box, [&](const double x[3], std::size_t index) {
      const double rhs[3] = {x[0] - p0[0], x[1] - p0[1], x[2] - p0[2]};
      const double r = vtkMath::Determinant3x3(rhs, c2, c3) / det;
      const double s1 = vtkMath::Determinant3x3(c1, rhs, c3) / det;
      const double t = vtkMath::Determinant3x3(c1, c2, rhs) / det;
      const double u = 1.0 - r - s1 - t;
      if (!(r >= lo && r <= hi && s1 >= lo && s1 <= hi && t >= lo && t <= hi && u >= lo && u <= hi))
        return;
      double badness = 0.0;
      for (double p : {r, s1, t, u})
        badness = std::max(badness, p < 0.0 ? -p : (p > 1.0 ? p - 1.0 : 0.0));
      if (badness >= double(best_[index])) return;
      w.weights[0] = u;
      w.weights[1] = r;
      w.weights[2] = s1;
      w.weights[3] = t;
      write(s, index, float(badness), w.ids.data(), 4, w.weights);
    });
  }

  // vtkHexahedron::EvaluatePosition (HexahedronInverse) without building one.
  void visitHexahedron(const Source& s, const IndexBox& box, Workspace& w) {
    const HexahedronInverse hexahedron(w.corners.data());
    double pcoords[3];
    forEachPoint(box, [&](const double x[3], std::size_t index) {
      if (hexahedron.locate(x, pcoords, w.weights.data()) != HexahedronInverse::Result::Inside)
        return;
      const double badness = parametricDistance(pcoords);
      if (badness < double(best_[index]))
        write(s, index, float(badness), w.ids.data(), 8, w.weights);
    });
  }

  // vtkVoxel::EvaluatePosition's arithmetic: no tolerance, so a point a voxel
  // holds lies in it (badness 0), and the first voxel that holds it keeps it.
  void visitVoxel(const Source& s, const IndexBox& box, Workspace& w) {
    const double* c = w.corners.data();
    const double extent[3] = {c[3] - c[0], c[7] - c[1], c[14] - c[2]};
    forEachPoint(box, [&](const double x[3], std::size_t index) {
      double p[3];
      for (int a = 0; a < 3; ++a) {
        p[a] = (x[a] - c[a]) / extent[a];
        if (!(p[a] >= 0.0 && p[a] <= 1.0)) return;
      }
      if (best_[index] <= 0.0f) return;
      const double rm = 1.0 - p[0], sm = 1.0 - p[1], tm = 1.0 - p[2];
      double* wt = w.weights.data();
      wt[0] = rm * sm * tm, wt[1] = p[0] * sm * tm, wt[2] = rm * p[1] * tm;
      wt[3] = p[0] * p[1] * tm, wt[4] = rm * sm * p[2], wt[5] = p[0] * sm * p[2];
      wt[6] = rm * p[1] * p[2], wt[7] = p[0] * p[1] * p[2];
      write(s, index, 0.0f, w.ids.data(), 8, w.weights);
    });
  }

  template <class F>
  void forEachPoint(const IndexBox& box, F&& f) const {
    double x[3];
    for (int k = box.lo.z; k <= box.hi.z; ++k) {
      x[2] = grid_.origin.z + k * grid_.spacing.z;
      for (int j = box.lo.y; j <= box.hi.y; ++j) {
        x[1] = grid_.origin.y + j * grid_.spacing.y;
        const std::size_t row = std::size_t(grid_.dims.x) *
                                (std::size_t(j) + std::size_t(grid_.dims.y) * std::size_t(k));
        for (int i = box.lo.x; i <= box.hi.x; ++i) {
          x[0] = grid_.origin.x + i * grid_.spacing.x;
          f(x, row + std::size_t(i));
        }
      }
    }
  }

  // vtkDataArray::InterpolateTuple's sum: weights times values in double.
  void write(const Source& s, std::size_t index, float badness, const vtkIdType* ids, std::size_t n,
             const std::vector<double>& weights) {
    best_[index] = badness;
    for (std::size_t a = 0; a < s.arrays.size(); ++a) {
      const ArrayView& v = s.arrays[a];
      float* out = &(*values_)[a][index * std::size_t(v.components)];
      for (int c = 0; c < v.components; ++c) {
        double sum = 0.0;
        for (std::size_t i = 0; i < n; ++i)
          sum += weights[i] * v.at(ids[i], c);
        out[c] = static_cast<float>(sum);
      }
    }
  }

  UniformGrid grid_;
  std::vector<Source> sources_;
  std::vector<int> components_;
  std::uint64_t cells_ = 0;
  int maxCellSize_ = 0;
  int axis_ = 0;
  Workspace workspace_;
  std::size_t slabs_ = 1;
  std::vector<int> slabOf_, slabBegin_;
  std::vector<std::size_t> slabStart_;
  std::vector<std::uint32_t> entries_;
  std::vector<float> best_;  // per grid point: how far outside its cell it lies
  std::vector<std::vector<float>>* values_ = nullptr;
};

}  // namespace

ResampledArrays resampleMeshes(std::span<const MeshSource> sources, const UniformGrid& grid,
                               const std::string& what) {
  for (int a = 0; a < 3; ++a)
    if (grid.dims[a] < 1)
      throw Error(concat("resampling: ", grid.dims[a], " points along ", "xyz"[a],
                         "; expected at least one"));
  if (sources.empty()) throw Error("resampling: no dataset to resample");
  return Resampler(sources, grid).run(what);
}

}  // namespace sandstorm
