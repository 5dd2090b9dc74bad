// resampleField(): the field trilinearly sampled (VectorField::sample) at the
// points of a bounds-preserving grid of `dims` points. Used for formats that
// have no library of their own to resample with (FGA, VF). Throws Error for
// non-positive dims.
#pragma once

#include "core/field/vector_field.h"

namespace sandstorm {

VectorField resampleField(const VectorField& field, const glm::ivec3& dims);

}  // namespace sandstorm
