#include "core/io/budget_advice.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/util/error.h"

namespace sandstorm {

std::string budgetValueAtLeast(double bytes) {
  // The configuration takes no budget below 1 MiB, and units up to TiB.
  static const char* names[] = {"MiB", "GiB", "TiB"};
  double value = std::max(bytes, 1048576.0) / 1048576.0;
  int unit = 0;
  while (value >= 1024.0 && unit < 2)
    value /= 1024.0, ++unit;
  // Three significant digits, rounded up.
  const int decimals = value >= 100.0 ? 0 : (value >= 10.0 ? 1 : 2);
  const double scale = std::pow(10.0, decimals);
  value = std::ceil(value * scale) / scale;
  char text[48];
  std::snprintf(text, sizeof text, "%.*f %s", decimals, value, names[unit]);
  return text;
}

std::string raiseBudget(double needed) {
  return concat("; raise field.memory_budget to at least ", budgetValueAtLeast(needed));
}

}  // namespace sandstorm
