#include "core/util/faster_choice.h"

#include <algorithm>

namespace sandstorm {
namespace {

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

FasterChoice::FasterChoice(int trials, int block, int keep)
    : trials_(std::max(trials, 1)),
      block_(std::max(block, 1)),
      keep_(std::max(keep, 1)),
      keepNext_(std::min(2 * trials_ * block_, keep_)) {}

FasterChoice::Run FasterChoice::next() {
  if (kept_ >= 0) {
    if (left_-- > 0) return {kept_, -1};
    // Kept long enough: try both again.
    kept_ = -1;
    trialStart_ = ticket_;
    blocks_.clear();
    times_[0].clear();
    times_[1].clear();
  }
  const int ticket = ticket_++;
  return {((ticket - trialStart_) / block_) % 2, ticket};
}

void FasterChoice::measured(int ticket, double ms) {
  if (kept_ >= 0 || ticket < trialStart_ || ticket >= ticket_ || !(ms >= 0.0)) return;
  const int block = (ticket - trialStart_) / block_;
  std::pair<int, double>& sum = blocks_[block];
  sum.first += 1;
  sum.second += ms;
  if (sum.first < block_) return;
  times_[std::size_t(block % 2)].push_back(sum.second);
  blocks_.erase(block);
  if (int(times_[0].size()) < trials_ || int(times_[1].size()) < trials_) return;
  kept_ = median(times_[1]) < median(times_[0]) ? 1 : 0;
  left_ = keepNext_;
  keepNext_ = std::min(2 * keepNext_, keep_);
}

}  // namespace sandstorm
