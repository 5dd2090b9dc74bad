#include "core/io/sampling_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <vtkDataSet.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>

#include "core/field/vector_field.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr std::size_t kSampledCells = 20000;

// The longest side of the boxes of cells taken evenly from every block.
std::vector<double> cellSizes(const std::vector<VtkBlock>& blocks) {
  vtkIdType total = 0;
  for (const VtkBlock& b : blocks)
    total += b.data->GetNumberOfCells();
  std::vector<double> sizes;
  if (total == 0) return sizes;
  const vtkIdType stride = std::max<vtkIdType>(1, total / vtkIdType(kSampledCells));
  vtkIdType offset = 0;
  for (const VtkBlock& b : blocks) {
    const vtkIdType cells = b.data->GetNumberOfCells();
    for (vtkIdType c = (stride - offset % stride) % stride; c < cells; c += stride) {
      double box[6];
      b.data->GetCellBounds(c, box);
      const double size = std::max({box[1] - box[0], box[3] - box[2], box[5] - box[4]});
      if (size > 0.0 && std::isfinite(size)) sizes.push_back(size);
    }
    offset += cells;
  }
  return sizes;
}

}  // namespace

SamplingBounds boundsOf(const std::vector<VtkBlock>& blocks) {
  SamplingBounds out;
  out.min = glm::dvec3(std::numeric_limits<double>::max());
  out.max = -out.min;
  for (const VtkBlock& b : blocks) {
    double box[6];
    b.data->GetBounds(box);
    for (double v : box)
      if (!std::isfinite(v))
        throw Error(concat("the points of ", b.name.empty() ? "the data" : "block '" + b.name + "'",
                           " are not all at finite places (NaN or Inf coordinates)"));
    for (int a = 0; a < 3; ++a) {
      out.min[a] = std::min(out.min[a], box[2 * a]);
      out.max[a] = std::max(out.max[a], box[2 * a + 1]);
    }
  }
  return out;
}

double cloudSpacing(const std::vector<VtkBlock>& blocks, const SamplingBounds& bounds) {
  const glm::dvec3 extent = bounds.max - bounds.min;
  const double longest = std::max({extent.x, extent.y, extent.z});
  vtkIdType points = 0;
  for (const VtkBlock& b : blocks)
    points += b.data->GetNumberOfPoints();
  double volume = 1.0;
  int axes = 0;
  for (int a = 0; a < 3; ++a)
    if (extent[a] > 1e-6 * longest) {
      volume *= extent[a];
      ++axes;
    }
  if (axes == 0) return 0.0;
  return std::pow(volume / double(std::max<vtkIdType>(points, 1)), 1.0 / axes);
}

glm::ivec3 meshResolution(const std::vector<VtkBlock>& blocks, const SamplingBounds& bounds,
                          double bytesPerPoint, std::size_t memoryBudget, std::string& note) {
  const glm::dvec3 extent = bounds.max - bounds.min;
  const double longest = std::max({extent.x, extent.y, extent.z});
  if (!(longest > 0.0) || !std::isfinite(longest)) {
    note = "the data has no extent: one grid point";
    return glm::ivec3(1);
  }
  // Axes shorter than a millionth of the longest are flat: one point.
  int axes = 0;
  for (int a = 0; a < 3; ++a)
    axes += extent[a] > 1e-6 * longest ? 1 : 0;
  std::vector<double> sizes = cellSizes(blocks);
  double spacing = 0.0;
  std::string from;
  if (!sizes.empty()) {
    std::nth_element(sizes.begin(), sizes.begin() + std::ptrdiff_t(sizes.size() / 2), sizes.end());
    spacing = sizes[sizes.size() / 2];
    from = concat("the cells' median size ", spacing, " m");
  } else {
    spacing = cloudSpacing(blocks, bounds);
    from = concat("the points' mean spacing ", spacing, " m");
  }
  // A few cells spread far apart do not make a fine grid worth its memory:
  // no more than 64 grid points a cell (or a data point), 32^3 at least.
  double cells = 0.0;
  for (const VtkBlock& b : blocks)
    cells += double(std::max(b.data->GetNumberOfCells(), b.data->GetNumberOfPoints()));
  const double cap = std::min({double(kDefaultPoints), double(VectorField::kMaxPoints),
                               double(memoryBudget) / std::max(bytesPerPoint, 1.0),
                               std::max(32768.0, 64.0 * cells)});
  auto dimsFor = [&](double h) {
    glm::ivec3 d(1);
    for (int a = 0; a < 3; ++a)
      if (extent[a] > 1e-6 * longest)
        d[a] = int(std::clamp(std::round(extent[a] / h) + 1.0, 2.0, 1e6));
    return d;
  };
  glm::ivec3 dims = dimsFor(spacing);
  bool capped = false;
  for (int tries = 0; tries < 200; ++tries) {
    const double points = double(dims.x) * dims.y * dims.z;
    if (points <= cap) break;
    capped = true;
    spacing *= std::max(1.01, std::pow(points / cap, 1.0 / std::max(axes, 1)));
    dims = dimsFor(spacing);
  }
  note = concat(
      "resampled to ", dims.x, " x ", dims.y, " x ", dims.z, " points spaced by ", from,
      capped ? concat(", coarsened to ", spacing, " m to stay within ", std::size_t(cap), " points")
             : std::string(),
      "; field.resolution (--dims) chooses another");
  return dims;
}

}  // namespace sandstorm
