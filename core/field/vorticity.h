// vorticityMagnitude: |curl v| at every grid point of a field (1/s when v is
// in m/s), from central differences (one-sided at the grid's edges and next
// to points without data; a derivative counts as 0 along an axis of one point
// or with no neighbour with data along it), as a VectorField whose
// x component holds it (so it is stored, uploaded and sampled like a field).
// Points without data stay without data. The field the particles feel is
// strength * placement applied to v; its vorticity is |strength| times this.
#pragma once

#include "core/field/vector_field.h"

namespace sandstorm {

VectorField vorticityMagnitude(const VectorField& field);

}  // namespace sandstorm
