#include "core/io/grid_resample.h"

namespace sandstorm {

VectorField resampleField(const VectorField& field, const glm::ivec3& dims) {
  VectorField out(field.bounds(), dims);
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i)
        out.at(i, j, k) = field.sample(out.pointPosition(i, j, k));
  return out;
}

}  // namespace sandstorm
