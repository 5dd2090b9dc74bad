// velocityGradient(): the field's derivatives at a grid point, from central
// differences (one-sided at the grid's edges and next to points without data;
// 0 along an axis of one point or with no neighbour with data along it).
// Column a is d v / d x_a, so the tensor J has J[a][c] = d v_c / d x_a.
#pragma once

#include <glm/glm.hpp>

#include "core/field/vector_field.h"

namespace sandstorm {

glm::mat3 velocityGradient(const VectorField& field, glm::ivec3 at);

}  // namespace sandstorm
