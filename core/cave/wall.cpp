#include "core/cave/wall.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/util/error.h"

namespace sandstorm {
namespace {

struct Basis {
  glm::vec3 right, up, normal;  // normal points from the screen towards the viewer
};

Basis basisOf(const WallCorners& w) {
  const glm::vec3 right = glm::normalize(w.lowerRight - w.lowerLeft);
  const glm::vec3 up = glm::normalize(w.upperLeft - w.lowerLeft);
  return {right, up, glm::normalize(glm::cross(right, up))};
}

}  // namespace

void validateWall(const WallCorners& w, const std::string& where, float tolerance) {
  const glm::vec3 across = w.lowerRight - w.lowerLeft, upward = w.upperLeft - w.lowerLeft;
  const float width = glm::length(across), height = glm::length(upward);
  for (const glm::vec3& c : {w.lowerLeft, w.lowerRight, w.upperLeft})
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
      throw Error(concat(where, ": corners must be finite numbers"));
  if (width < 1e-3f || height < 1e-3f)
    throw Error(concat(where, ": the wall is ", width, " m wide and ", height,
                       " m high; expected a rectangle of positive size"));
  const float cosine = std::abs(glm::dot(across, upward)) / (width * height);
  if (cosine > tolerance)
    throw Error(
        concat(where, ": the corners are not a rectangle: the lower and left edges meet at ",
               glm::degrees(
                   std::acos(std::clamp(glm::dot(across, upward) / (width * height), -1.0f, 1.0f))),
               " degrees; expected 90"));
}

Frustum offAxisFrustum(const WallCorners& w, const glm::vec3& eye, float n, float f) {
  const Basis b = basisOf(w);
  const glm::vec3 va = w.lowerLeft - eye, vb = w.lowerRight - eye, vc = w.upperLeft - eye;
  // Distance from the eye to the screen plane; an eye on or behind the plane
  // sees the wall edge-on or from behind: keep a sliver so the matrix stays finite.
  const float d = std::max(-glm::dot(va, b.normal), 1e-4f);
  const float scale = n / d;
  return {glm::dot(b.right, va) * scale,
          glm::dot(b.right, vb) * scale,
          glm::dot(b.up, va) * scale,
          glm::dot(b.up, vc) * scale,
          n,
          f};
}

View offAxisView(const WallCorners& w, const glm::vec3& eye, float n, float f) {
  const Basis b = basisOf(w);
  const Frustum fr = offAxisFrustum(w, eye, n, f);
  glm::mat4 rotation(1.0f);  // rows: right, up, normal
  for (int c = 0; c < 3; ++c) {
    rotation[c][0] = b.right[c];
    rotation[c][1] = b.up[c];
    rotation[c][2] = b.normal[c];
  }
  View v;
  v.view = rotation * glm::translate(glm::mat4(1.0f), -eye);
  v.projection = glm::frustum(fr.left, fr.right, fr.bottom, fr.top, fr.nearPlane, fr.farPlane);
  v.eye = eye;
  return v;
}

}  // namespace sandstorm
