// Wall: a rectangular screen in the room, given by three corners in metres
// (lower-left, lower-right, upper-left; upper-right is derived), and the
// generalized off-axis perspective projection for an eye in front of it
// (Kooima, "Generalized Perspective Projection", 2009).
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "core/cave/view.h"

namespace sandstorm {

struct WallCorners {
  glm::vec3 lowerLeft{0.0f};
  glm::vec3 lowerRight{0.0f};
  glm::vec3 upperLeft{0.0f};
  glm::vec3 upperRight() const { return lowerRight + upperLeft - lowerLeft; }
};

// Throws Error (prefixed with `where`) unless the corners span a rectangle of
// positive size: both edges longer than 1 mm and perpendicular within
// `tolerance` (the cosine of the angle between them).
void validateWall(const WallCorners& corners, const std::string& where, float tolerance = 1e-3f);

struct Frustum {
  float left, right, bottom, top, nearPlane, farPlane;
};

// The frustum extents on the near plane for an eye (Kooima's l, r, b, t).
Frustum offAxisFrustum(const WallCorners& wall, const glm::vec3& eye, float nearPlane,
                       float farPlane);

// The view of the room through the wall for one eye: projection = frustum(...),
// view = (screen basis)^T * translate(-eye).
View offAxisView(const WallCorners& wall, const glm::vec3& eye, float nearPlane, float farPlane);

}  // namespace sandstorm
