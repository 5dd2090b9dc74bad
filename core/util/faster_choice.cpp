#include "core/util/faster_choice.h"

#include <algorithm>

namespace sandstorm {
namespace {

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

FasterChoice::FasterChoice(int trials, int keep)
    : trials_(std::max(trials, 1)), keep_(std::max(keep, 1)) {}

int FasterChoice::next() {
  if (kept_ >= 0) {
    if (left_-- > 0) return kept_;
    // Kept long enough: try both again.
    kept_ = -1;
    ++trial_;
    times_[0].clear();
    times_[1].clear();
  }
  const int way = turn_;
  turn_ = 1 - turn_;
  return way;
}

void FasterChoice::measured(int way, double ms, int trial) {
  if (kept_ >= 0 || trial != trial_ || way < 0 || way > 1 || !(ms >= 0.0)) return;
  times_[std::size_t(way)].push_back(ms);
  if (int(times_[0].size()) < trials_ || int(times_[1].size()) < trials_) return;
  kept_ = median(times_[1]) < median(times_[0]) ? 1 : 0;
  left_ = keep_;
}

}  // namespace sandstorm
