// stateColorScale: the colour scale a state shows with a field: its
// render.color_* attributes resolved against the field's range as the
// particles feel it (sim.field_strength, the placement's scale). What every
// wall, the menu and the legend use.
#pragma once

#include "core/color/color_scale.h"
#include "core/sim/frame_packet.h"

namespace sandstorm {

ColorScale stateColorScale(const ParticleState& state, const FieldUpdate* field);

}  // namespace sandstorm
