#include "contexts/render/frame_blocks.h"

#include "core/sim/state_color_scale.h"

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

RenderBlock makeRenderBlock(const ParticleState& state, const FieldUpdate* field, float blend,
                            const ColorMap::Table& table) {
  const RenderSettings& s = state.render;
  RenderBlock b{};
  b.colorBirth = glm::vec4(s.colorBirth, s.opacityBirth);
  b.colorDeath = glm::vec4(s.colorDeath, s.opacityDeath);
  const float len = glm::length(s.lightDirection);
  const glm::vec3 light = len > 0.0f ? s.lightDirection / len : glm::vec3(0, 0, 1);
  b.lightDirection = glm::vec4(light, s.ambient);
  b.params = glm::vec4(s.size, s.softness, s.mode != RenderMode::Points ? 1.0f : 0.0f, s.shutter);
  b.light = glm::vec4(s.lightColor * s.lightStrength, s.shadows ? 1.0f : 0.0f);
  b.haze = glm::vec4(s.scattering, 0.0f, 0.0f, 0.0f);
  b.splat = glm::vec4(s.splatDetail, s.splatOverlap, 0.0f, 0.0f);
  const ColorScale scale = stateColorScale(state, field);
  b.colorScale =
      glm::vec4(float(int(scale.quantity)), scale.low, scale.high, scale.log ? 1.0f : 0.0f);
  for (std::size_t i = 0; i < table.size(); ++i)
    b.colorTable[i] = glm::vec4(table[i], 1.0f);
  if (field && field->colorGrid) {
    const VectorField& w = *field->colorGrid;
    b.fieldMin = glm::vec4(w.bounds().min, 0.0f);
    b.fieldIndexScale = glm::vec4(w.indexScale(), 0.0f);
    b.fieldDims = glm::ivec4(w.dims(), 1);
    b.placementOffset = glm::vec4(field->placement.offset, field->placement.scale);
    for (int c = 0; c < 3; ++c)
      b.placementRotation[c] = glm::vec4(field->placement.rotation[c], 0.0f);
    b.colorGrid = glm::vec4(
        field->nextColorGrid ? blend : 0.0f, field->nextColorGrid ? 1.0f : 0.0f,
        scale.quantity == ColorQuantity::Vorticity ? std::abs(state.sim.fieldStrength) : 1.0f,
        1.0f);
  }
  return b;
}

}  // namespace sandstorm
