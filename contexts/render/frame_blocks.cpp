#include "contexts/render/frame_blocks.h"

namespace sandstorm {

ViewBlock makeViewBlock(const View& v, glm::ivec2 size) {
  ViewBlock b;
  b.view = v.view;
  b.projection = v.projection;
  b.viewProjection = v.projection * v.view;
  b.inverseViewProjection = glm::inverse(b.viewProjection);
  b.eye = glm::vec4(v.eye, 1.0f);
  b.viewport = glm::vec4(0.0f, 0.0f, float(size.x), float(size.y));
  return b;
}

RenderBlock makeRenderBlock(const RenderSettings& s, const FieldRange& field) {
  RenderBlock b;
  b.colorBirth = glm::vec4(s.colorBirth, s.opacityBirth);
  b.colorDeath = glm::vec4(s.colorDeath, s.opacityDeath);
  const float len = glm::length(s.lightDirection);
  const glm::vec3 light = len > 0.0f ? s.lightDirection / len : glm::vec3(0, 0, 1);
  b.lightDirection = glm::vec4(light, s.ambient);
  b.params = glm::vec4(s.size, s.softness, s.mode != RenderMode::Points ? 1.0f : 0.0f, 0.0f);
  const ColorScale scale =
      resolveColorScale(s.colorBy, s.colorRange, s.colorMin, s.colorMax, s.colorLog, field);
  b.colorScale =
      glm::vec4(float(int(scale.quantity)), scale.low, scale.high, scale.log ? 1.0f : 0.0f);
  const ColorMap::Table table = ColorMap(s.colorMap, s.colorBirth, s.colorDeath).gpuTable();
  for (std::size_t i = 0; i < table.size(); ++i)
    b.colorTable[i] = glm::vec4(table[i], 1.0f);
  return b;
}

}  // namespace sandstorm
