#include "core/flow/slice_arrows.h"

#include <algorithm>
#include <cmath>

namespace sandstorm {
namespace {

// Inside the convex polygon (corners in order), in the plane's 2D coordinates.
bool inside(const std::vector<glm::vec2>& corners, const glm::vec2& p) {
  float sign = 0.0f;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const glm::vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
    const float cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    if (cross == 0.0f) continue;
    if (sign == 0.0f) sign = cross;
    if ((cross > 0.0f) != (sign > 0.0f)) return false;
  }
  return true;
}

}  // namespace

std::vector<SliceArrow> sliceArrows(const std::vector<glm::vec3>& polygon, const glm::vec3& normal,
                                    int perSide, const PhysicsInputs& in) {
  std::vector<SliceArrow> arrows;
  if (polygon.size() < 3 || perSide < 1 || !in.field || !(glm::length(normal) > 0.0f))
    return arrows;
  const glm::vec3 n = glm::normalize(normal);
  // An in-plane basis: u along the first edge, v = n x u.
  const glm::vec3 u = glm::normalize(polygon[1] - polygon[0]), v = glm::cross(n, u);
  std::vector<glm::vec2> corners;
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& c : polygon) {
    const glm::vec2 q(glm::dot(c - polygon[0], u), glm::dot(c - polygon[0], v));
    corners.push_back(q);
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  const glm::vec2 extent = hi - lo;
  const float spacing = std::max(extent.x, extent.y) / float(perSide);
  if (!(spacing > 0.0f)) return arrows;
  const glm::ivec2 cells = glm::max(glm::ivec2(glm::ceil(extent / spacing)), glm::ivec2(1));
  // Grid points at cell centres, so none sits on the polygon's edge.
  float fastest = 0.0f;
  for (int j = 0; j < cells.y; ++j)
    for (int i = 0; i < cells.x; ++i) {
      const glm::vec2 q = lo + spacing * (glm::vec2(i, j) + 0.5f);
      if (!inside(corners, q)) continue;
      const glm::vec3 p = polygon[0] + q.x * u + q.y * v;
      const glm::vec3 local = in.placement.toLocal(p);
      if (!in.field->bounds().contains(local) || !in.field->cellValid(local)) continue;
      const glm::vec3 w = fieldAt(p, in);
      const glm::vec3 along = w - glm::dot(w, n) * n;
      const float speed = glm::length(along);
      if (!(speed > 0.0f) || !std::isfinite(speed)) continue;
      fastest = std::max(fastest, speed);
      arrows.push_back({p, along, w});  // tip holds the in-plane velocity until scaled
    }
  for (SliceArrow& a : arrows)
    a.tip = a.base + a.tip * (0.9f * spacing / fastest);
  return arrows;
}

std::vector<glm::vec3> arrowLines(const std::vector<SliceArrow>& arrows, const glm::vec3& normal) {
  std::vector<glm::vec3> lines;
  lines.reserve(arrows.size() * 6);
  const glm::vec3 n = glm::length(normal) > 0.0f ? glm::normalize(normal) : glm::vec3(0, 0, 1);
  for (const SliceArrow& a : arrows) {
    const glm::vec3 shaft = a.tip - a.base;
    const glm::vec3 side = glm::cross(n, shaft);  // in the plane, as long as the shaft
    lines.insert(lines.end(), {a.base, a.tip, a.tip, a.tip - 0.3f * shaft + 0.15f * side, a.tip,
                               a.tip - 0.3f * shaft - 0.15f * side});
  }
  return lines;
}

}  // namespace sandstorm
