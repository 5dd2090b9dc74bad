#include "core/field/analytic_field.h"

namespace sandstorm {

VectorField bake(const AnalyticField& field, const Box& bounds, const glm::ivec3& dims) {
  VectorField grid(bounds, dims);
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i)
        grid.at(i, j, k) = field.evaluate(grid.pointPosition(i, j, k));
  return grid;
}

}  // namespace sandstorm
