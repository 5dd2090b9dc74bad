// resampleMeshes(): point arrays of VTK datasets (unstructured grids, polydata,
// structured grids, image data: any cells VTK has, any mix of blocks) sampled
// at the points of a uniform grid, the way vtkProbeFilter (ParaView's Resample
// To Image) samples them, but cell by cell on every core instead of point by
// point through a cell locator.
//
// A grid point takes the values interpolated in the cell that holds it: the
// cell's own interpolation weights (VTK's EvaluatePosition; for linear
// tetrahedra and hexahedra, and a 3D structured or rectilinear grid's cells,
// the same arithmetic inline, without a vtkCell each) applied to the cell's point values
// in double precision, rounded to float. A point is held by a 3D cell when
// its parametric coordinates lie within the cell (within VTK's tolerance for
// the cell's type: 0.001 in parametric units for a tetrahedron, 1e-6 for a
// hexahedron, none for a voxel), by a 2D or 1D cell within a thousandth of the cell's size
// of it. Where several cells hold a point (on a shared face, or within the
// tolerance of one cell and inside another) the one it lies deepest in wins,
// and among equals the first (sources in order, cells by id), so the result
// does not depend on the threads' timing. Points no cell holds are invalid
// (their values zero). Ghost cells (vtkGhostType's duplicate or hidden bits,
// as pieces of a parallel file carry them) are skipped.
//
// The work: each cell's box in grid indices, the grid cut into slabs along
// its longest axis, each slab's cells visited by one thread at a time over
// the grid points of their boxes. Progress is logged for long runs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

class vtkDataArray;
class vtkDataSet;

namespace sandstorm {

// Point (i, j, k) sits at origin + spacing * (i, j, k), as in vtkImageData.
struct UniformGrid {
  glm::dvec3 origin{0.0};
  glm::dvec3 spacing{1.0};
  glm::ivec3 dims{1};
  std::size_t points() const { return std::size_t(dims.x) * dims.y * dims.z; }
};

struct MeshSource {
  vtkDataSet* data = nullptr;
  // Point arrays of `data`, in output order; the same component counts in
  // every source.
  std::vector<vtkDataArray*> arrays;
};

struct ResampledArrays {
  // One per array: components x grid points, components fastest, then x.
  std::vector<std::vector<float>> values;
  std::vector<std::uint8_t> valid;  // 1 where a cell holds the point
  std::size_t validCount = 0;
};

// `what` names the work in progress lines ("resampling wind.vtu"). Throws
// Error when the sources disagree on their arrays or hold more than 2^32 cells.
ResampledArrays resampleMeshes(std::span<const MeshSource> sources, const UniformGrid& grid,
                               const std::string& what);

}  // namespace sandstorm
