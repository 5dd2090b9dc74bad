#include "core/util/progress_board.h"

#include <algorithm>
#include <cstdio>

#include "core/util/progress_meter.h"

namespace sandstorm {
namespace {

// Bytes in the units a person reads them in ("572.0 MB"); other units as
// counts, without the unit ("572000"; a rate in two figures: "1.2e+06").
std::string amount(double v, const std::string& unit, bool rate = false) {
  char text[48];
  if (unit == "bytes") {
    const char* names[] = {"bytes", "KB", "MB", "GB", "TB"};
    int i = 0;
    while (v >= 1000.0 && i < 4)
      v /= 1000.0, ++i;
    std::snprintf(text, sizeof text, i == 0 ? "%.0f %s" : "%.1f %s", v, names[i]);
  } else {
    std::snprintf(text, sizeof text, rate && v >= 1e5 ? "%.2g" : "%.0f", v);
  }
  return text;
}

// A count in its unit: "572.0 MB", "572000 cells".
std::string counted(double v, const std::string& unit, bool rate = false) {
  return unit == "bytes" ? amount(v, unit) : amount(v, unit, rate) + " " + unit;
}

}  // namespace

double ProgressSnapshot::fraction() const {
  return total == 0 ? 0.0 : std::min(1.0, double(done) / double(total));
}

std::string ProgressSnapshot::text() const {
  const std::string perSecond = counted(rate, unit, true) + "/s";
  if (total == 0) return what + ": " + counted(double(done), unit) + ", " + perSecond;
  char tail[160];
  std::snprintf(tail, sizeof tail, "%d%% (%s of %s), %s, %.1f s left", int(100.0 * fraction()),
                amount(double(done), unit).c_str(), counted(double(total), unit).c_str(),
                perSecond.c_str(), secondsLeft);
  return what + ": " + tail;
}

ProgressBoard& ProgressBoard::instance() {
  static ProgressBoard board;
  return board;
}

std::optional<ProgressSnapshot> ProgressBoard::snapshot() const {
  std::lock_guard lock(mutex_);
  if (meters_.empty()) return std::nullopt;
  return meters_.back()->snapshot();
}

void ProgressBoard::add(const ProgressMeter* meter) {
  std::lock_guard lock(mutex_);
  meters_.push_back(meter);
}

void ProgressBoard::remove(const ProgressMeter* meter) {
  std::lock_guard lock(mutex_);
  meters_.erase(std::remove(meters_.begin(), meters_.end(), meter), meters_.end());
}

}  // namespace sandstorm
