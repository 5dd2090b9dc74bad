#include "core/color/color_legend.h"

#include <cmath>
#include <cstdio>

namespace sandstorm {
namespace {

std::string label(double value, double step) {
  char text[32];
  const double magnitude = std::max(std::abs(value), step);
  if (magnitude >= 1e5 || step < 1e-4) {
    std::snprintf(text, sizeof text, "%.3g", value);
  } else {
    const int decimals = step >= 1.0 ? 0 : int(std::ceil(-std::log10(step) - 1e-9));
    std::snprintf(text, sizeof text, "%.*f", decimals, std::abs(value) < step * 1e-6 ? 0.0 : value);
  }
  return text;
}

}  // namespace

double niceStep(double low, double high, int target) {
  const double span = high - low;
  if (!(span > 0.0) || target < 1) return 1.0;
  const double raw = span / target;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  const double fraction = raw / power;
  // The smallest nice step at least the raw one: at most `target` + 1 ticks.
  const double nice = fraction <= 1.0 ? 1.0 : fraction <= 2.0 ? 2.0 : fraction <= 5.0 ? 5.0 : 10.0;
  return nice * power;
}

double smallerNiceStep(double step) {
  const double power = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  const double fraction = step / power;
  return fraction > 4.5 ? 2.0 * power : fraction > 1.5 ? power : 0.5 * power;
}

ColorLegend ColorLegend::of(const ColorScale& scale, int targetTicks) {
  ColorLegend legend;
  const std::string_view unit = quantityUnit(scale.quantity);
  legend.title = scale.quantity == ColorQuantity::Array && !scale.arrayName.empty()
                     ? scale.arrayName
                     : std::string(quantityName(scale.quantity));
  if (!unit.empty()) legend.title += " (" + std::string(unit) + ")";
  if (scale.log) legend.title += ", log scale";
  const double low = scale.low, high = scale.high;
  auto add = [&](double value, double step) {
    legend.ticks.push_back({float(value), scale.coordinate(float(value)), label(value, step)});
  };
  if (!(high > low)) {
    add(low, std::max(std::abs(low) * 1e-3, 1e-3));
    legend.ticks.back().t = 0.5f;
    return legend;
  }
  if (scale.log) {
    const int first = int(std::floor(std::log10(low))), last = int(std::ceil(std::log10(high)));
    const bool fewDecades = std::log10(high / low) < 3.0;
    for (int e = first; e <= last; ++e) {
      const double decade = std::pow(10.0, e);
      for (const double m : {1.0, 2.0, 5.0}) {
        if (m != 1.0 && !fewDecades) continue;
        const double v = m * decade;
        if (v >= low * (1.0 - 1e-6) && v <= high * (1.0 + 1e-6)) add(v, v);
      }
    }
    if (legend.ticks.size() >= 2) return legend;
    legend.ticks.clear();  // within a decade (1.5 to 1.9): the linear ticks, placed on the log bar
  }
  // A bar with one label says nothing of its scale: the step shrinks (5, 2, 1
  // times a power of ten) until at least two ticks fall inside the range.
  double step = niceStep(low, high, targetTicks);
  auto ticks = [&](double s) {
    const double tolerance = s * 1e-6;
    return std::floor((high + tolerance) / s) - std::ceil((low - tolerance) / s) + 1.0;
  };
  while (ticks(step) < 2.0)
    step = smallerNiceStep(step);
  const double tolerance = step * 1e-6;
  for (double k = std::ceil((low - tolerance) / step);; k += 1.0) {
    const double v = k * step;
    if (v > high + tolerance) break;
    add(v, step);
  }
  return legend;
}

}  // namespace sandstorm
