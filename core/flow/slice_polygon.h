// slicePolygon: where a plane cuts a placed field's box: the convex polygon
// (3 to 6 corners, in order around it) in the particles' coordinates, or
// nothing when the plane misses the box or its normal is zero.
#pragma once

#include <vector>

#include "core/field/box.h"
#include "core/field/field_placement.h"

namespace sandstorm {

// `box`: the field's bounds in its own coordinates; `origin`, `normal`: the
// plane, in the particles' coordinates (room = placement.toRoom(local)).
std::vector<glm::vec3> slicePolygon(const Box& box, const FieldPlacement& placement,
                                    const glm::vec3& origin, const glm::vec3& normal);

}  // namespace sandstorm
