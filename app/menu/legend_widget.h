// drawColorLegend: a colour bar with its title, ticks and labels, as Dear
// ImGui widgets in the current window: the menu's "Look" section and the
// legend a wall shows (LegendHost) draw the same bar.
#pragma once

#include "core/color/color_legend.h"
#include "core/color/color_map.h"

namespace sandstorm {

// `width`: the bar's width in pixels. Shows `scale.note` under the bar, if any.
void drawColorLegend(const ColorScale& scale, const ColorMap& map, float width);

}  // namespace sandstorm
