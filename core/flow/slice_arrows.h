// sliceArrows: arrow glyphs on the slice plane (slice.arrows), as ParaView's
// Glyph filter draws on a slice: a square grid in the plane, `perSide` points
// along the polygon's longer side, and at each grid point inside the slice
// (and inside the field's data) an arrow of the field there as the particles
// feel it (fieldAt), projected into the plane so it reads on it, scaled so
// the fastest arrow spans 0.9 of the grid spacing. Each arrow is three line
// segments: the shaft and the two strokes of its head.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "core/sim/particle_physics.h"

namespace sandstorm {

struct SliceArrow {
  glm::vec3 base{0.0f};      // the grid point
  glm::vec3 tip{0.0f};       // base + the scaled in-plane velocity
  glm::vec3 velocity{0.0f};  // the field there (whole, before projection)
};

// `polygon`: slicePolygon's corners (particles' coordinates); `normal`: the
// plane's. Arrows of zero in-plane velocity are left out.
std::vector<SliceArrow> sliceArrows(const std::vector<glm::vec3>& polygon, const glm::vec3& normal,
                                    int perSide, const PhysicsInputs& in);

// The arrows as line segments (pairs of points): shaft, then the head's two strokes.
std::vector<glm::vec3> arrowLines(const std::vector<SliceArrow>& arrows, const glm::vec3& normal);

}  // namespace sandstorm
