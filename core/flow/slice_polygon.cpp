#include "core/flow/slice_polygon.h"

#include <algorithm>
#include <cmath>

namespace sandstorm {

std::vector<glm::vec3> slicePolygon(const Box& box, const FieldPlacement& placement,
                                    const glm::vec3& origin, const glm::vec3& normal) {
  if (!(glm::length(normal) > 0.0f)) return {};
  // The plane in the field's coordinates: the placement turns and scales
  // uniformly, so a normal only turns.
  const glm::vec3 o = placement.toLocal(origin);
  const glm::vec3 n = glm::normalize(glm::transpose(placement.rotation) * normal);
  glm::vec3 corner[8];
  for (int c = 0; c < 8; ++c)
    corner[c] = {c & 1 ? box.max.x : box.min.x, c & 2 ? box.max.y : box.min.y,
                 c & 4 ? box.max.z : box.min.z};
  // The box's 12 edges: corners that differ in one bit.
  std::vector<glm::vec3> cut;
  for (int a = 0; a < 8; ++a)
    for (int bit = 1; bit < 8; bit <<= 1) {
      const int b = a | bit;
      if (b == a) continue;
      const float da = glm::dot(corner[a] - o, n), db = glm::dot(corner[b] - o, n);
      if ((da < 0.0f) == (db < 0.0f) && da != 0.0f && db != 0.0f) continue;
      const float t = da == db ? 0.0f : da / (da - db);
      const glm::vec3 p = corner[a] + t * (corner[b] - corner[a]);
      // A plane through a corner cuts three edges there: keep the point once.
      if (std::none_of(cut.begin(), cut.end(), [&](const glm::vec3& q) {
            return glm::length(q - p) <= 1e-6f * (1.0f + glm::length(p));
          }))
        cut.push_back(p);
    }
  if (cut.size() < 3) return {};
  // In order around the centre, seen along the normal.
  glm::vec3 centre(0.0f);
  for (const glm::vec3& p : cut)
    centre += p;
  centre /= float(cut.size());
  const glm::vec3 u = glm::normalize(cut[0] - centre), v = glm::cross(n, u);
  std::sort(cut.begin(), cut.end(), [&](const glm::vec3& p, const glm::vec3& q) {
    return std::atan2(glm::dot(p - centre, v), glm::dot(p - centre, u)) <
           std::atan2(glm::dot(q - centre, v), glm::dot(q - centre, u));
  });
  for (glm::vec3& p : cut)
    p = placement.toRoom(p);
  return cut;
}

}  // namespace sandstorm
