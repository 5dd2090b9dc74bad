// composeField: the field editor's result, the field in use with its
// primitives added: at every point of `base` (in the field's own coordinates)
// the active primitives' velocities at that point's room position
// (placement.toRoom), carried into the field's frame (vectorToLocal), are
// added to the base's. The grid keeps base's bounds, dims, validity and scalar
// arrays, so the walls treat it like any field. `pool` splits the points over
// threads (null: this thread); the sum is the same either way.
#pragma once

#include <span>

#include "core/editor/field_primitive.h"
#include "core/field/field_placement.h"
#include "core/field/vector_field.h"

namespace sandstorm {

class ParallelFor;

VectorField composeField(const VectorField& base, const FieldPlacement& placement,
                         std::span<const FieldPrimitive> primitives, ParallelFor* pool = nullptr);

}  // namespace sandstorm
