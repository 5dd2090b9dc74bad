#include "core/cave/window_segments.h"

namespace sandstorm {

std::vector<WindowSegment> windowSegments(const glm::mat4& viewProjection, glm::vec2 size,
                                          std::span<const std::array<glm::vec3, 2>> world) {
  std::vector<WindowSegment> out;
  for (const auto& [from, to] : world) {
    glm::vec4 p = viewProjection * glm::vec4(from, 1.0f), q = viewProjection * glm::vec4(to, 1.0f);
    bool visible = true;
    // Near (z >= -w) and far (z <= w) planes: the part on the inner side.
    for (const float side : {1.0f, -1.0f}) {
      const float dp = p.w + side * p.z, dq = q.w + side * q.z;
      if (dp < 0.0f && dq < 0.0f) {
        visible = false;
        break;
      }
      if (dp < 0.0f) p += (q - p) * (dp / (dp - dq));
      if (dq < 0.0f) q += (p - q) * (dq / (dq - dp));
    }
    if (!visible || p.w <= 0.0f || q.w <= 0.0f) continue;
    const auto window = [&](const glm::vec4& c) {
      const glm::vec3 ndc = glm::vec3(c) / c.w;
      return glm::vec3((ndc.x * 0.5f + 0.5f) * size.x, (ndc.y * 0.5f + 0.5f) * size.y,
                       ndc.z * 0.5f + 0.5f);
    };
    out.push_back({window(p), window(q)});
  }
  return out;
}

std::array<std::array<glm::vec3, 2>, 12> boxEdges(const glm::mat4& model) {
  const auto corner = [&](int i) {
    return glm::vec3(model *
                     glm::vec4(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1), 1.0f));
  };
  std::array<std::array<glm::vec3, 2>, 12> edges;
  int n = 0;
  for (int i = 0; i < 8; ++i)
    for (int axis = 0; axis < 3; ++axis)
      if (!(i & (1 << axis))) edges[std::size_t(n++)] = {corner(i), corner(i | (1 << axis))};
  return edges;
}

}  // namespace sandstorm
