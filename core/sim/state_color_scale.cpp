#include "core/sim/state_color_scale.h"

namespace sandstorm {

ColorScale stateColorScale(const ParticleState& state, const FieldUpdate* field) {
  const RenderSettings& r = state.render;
  const float strength = state.sim.fieldStrength;
  const FieldFeel feel{strength * (field ? field->placement.scale : 1.0f), strength};
  ColorScale scale = resolveColorScale(r.colorBy, r.colorRange, r.colorMin, r.colorMax, r.colorLog,
                                       field ? field->range : FieldRange{}, feel);
  if (r.colorBy == ColorQuantity::Array)
    scale.arrayName = field && field->colorGrid ? field->colorArray : r.colorArray;
  return scale;
}

}  // namespace sandstorm
