// ColorLegend: what a colour bar shows: the quantity's name and unit, the
// scale's ends, and tick values at "nice" numbers (1, 2 or 5 times a power of
// ten on a linear scale; powers of ten, with 2 and 5 between them when there
// are few decades, on a log scale), each with its place t on the bar and a
// label. Pure geometry and text: the menu and the walls draw it.
#pragma once

#include <string>
#include <vector>

#include "core/color/color_scale.h"

namespace sandstorm {

struct LegendTick {
  float value = 0.0f;
  float t = 0.0f;  // along the bar, 0 at the low end
  std::string label;
};

struct ColorLegend {
  std::string title;  // "speed (m/s)"
  std::vector<LegendTick> ticks;

  // At most `targetTicks` + 1 ticks inside [low, high] on a linear scale, but
  // at least two where the range is not flat (then more, at a finer step, when
  // the nice step leaves one: 1.00 .. 1.044 with two asked for has 1.00, 1.02,
  // 1.04). A log scale within a decade takes the linear ticks.
  static ColorLegend of(const ColorScale& scale, int targetTicks = 5);
};

// The step of a linear axis from `low` to `high` with at most `target` + 1
// ticks: the smallest of 1, 2 or 5 times a power of ten at least (high - low) / target.
double niceStep(double low, double high, int target);
// The next nice step below `step` (one of 1, 2 or 5 times a power of ten): 5 -> 2 -> 1 -> 0.5.
double smallerNiceStep(double step);

}  // namespace sandstorm
