#include "core/io/grid_resample.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/util/parallel_for.h"

namespace sandstorm {

VectorField resampleField(const VectorField& field, const glm::ivec3& dims) {
  VectorField out(field.bounds(), dims);
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i)
        out.at(i, j, k) = field.sample(out.pointPosition(i, j, k));
  return out;
}

namespace {

// Whether p lies in `box`, within a millionth of the box's size for the
// rounding of two grids' point positions (a flat axis: exactly on it).
bool inside(const Box& box, const glm::vec3& p) {
  const glm::vec3 size = box.max - box.min;
  const float tolerance = 1e-6f * std::max({size.x, size.y, size.z});
  for (int a = 0; a < 3; ++a)
    if (p[a] < box.min[a] - tolerance || p[a] > box.max[a] + tolerance) return false;
  return true;
}

}  // namespace

VectorField resampleOnto(const VectorField& step, const VectorField& grid) {
  const glm::ivec3 d = grid.dims();
  VectorField out(grid.bounds(), d);
  std::vector<std::uint8_t> valid(out.pointCount(), 1);
  std::vector<std::vector<float>> scalars(step.scalars().size(),
                                          std::vector<float>(out.pointCount(), 0.0f));
  const std::size_t layer = std::size_t(d.x) * std::size_t(d.y);
  std::span<glm::vec3> values = out.values();
  forChunks(
      std::size_t(d.z),
      [&](std::size_t firstLayer, std::size_t lastLayer) {
        for (int k = int(firstLayer); k < int(lastLayer); ++k)
          for (int j = 0; j < d.y; ++j)
            for (int i = 0; i < d.x; ++i) {
              const std::size_t n = out.index(i, j, k);
              const glm::vec3 p = out.pointPosition(i, j, k);
              if (!inside(step.bounds(), p) || (step.hasValidity() && !step.cellValid(p))) {
                valid[n] = 0;
                continue;
              }
              values[n] = step.sample(p);
              for (std::size_t s = 0; s < scalars.size(); ++s)
                scalars[s][n] = step.sampleScalars(step.scalars()[s], p);
            }
      },
      std::max<std::size_t>(1, (std::size_t{1} << 16) / std::max<std::size_t>(layer, 1)));
  out.setValidity(std::move(valid));
  for (std::size_t s = 0; s < scalars.size(); ++s)
    out.addScalars(step.scalars()[s].name, std::move(scalars[s]));
  if (grid.halfPrecision()) out.roundToHalf();
  return out;
}

}  // namespace sandstorm
