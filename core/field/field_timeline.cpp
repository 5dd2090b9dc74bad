#include "core/field/field_timeline.h"

#include <algorithm>
#include <cmath>

#include "core/field/grid_match.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

void checkTimes(const std::vector<double>& times) {
  if (times.empty()) throw Error("FieldTimeline: no frames");
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!std::isfinite(times[i]))
      throw Error(concat("FieldTimeline: frame ", i, "'s time is not finite"));
    if (i > 0 && !(times[i] > times[i - 1]))
      throw Error(concat("FieldTimeline: frame ", i, "'s time ", times[i], " does not follow ",
                         times[i - 1]));
  }
}

}  // namespace

FieldTimeline::FieldTimeline(std::vector<double> times,
                             std::vector<std::shared_ptr<const VectorField>> frames)
    : times_(std::move(times)), frames_(std::move(frames)) {
  if (frames_.empty() || frames_.size() != times_.size())
    throw Error(concat("FieldTimeline: ", frames_.size(), " frames for ", times_.size(), " times"));
  checkTimes(times_);
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    if (!frames_[i]) throw Error(concat("FieldTimeline: frame ", i, " is missing"));
    if (const std::string difference = gridDifference(*frames_[i], *frames_[0]);
        !difference.empty())
      throw Error(
          concat("step ", i, " has ", difference, "; expected every step on the same grid"));
  }
}

FieldTimeline::FieldTimeline(std::vector<double> times, std::shared_ptr<FieldSteps> steps)
    : times_(std::move(times)), steps_(std::move(steps)) {
  if (!steps_) throw Error("FieldTimeline: no steps to stream");
  checkTimes(times_);
}

std::shared_ptr<const VectorField> FieldTimeline::frame(std::size_t i) const {
  return steps_ ? steps_->get(i) : frames_[i];
}

std::shared_ptr<const VectorField> FieldTimeline::wait(std::size_t i) const {
  return steps_ ? steps_->wait(i) : frames_[i];
}

void FieldSteps::append(const std::filesystem::path&, std::shared_ptr<const VectorField>) {
  throw Error("FieldTimeline: this series takes no appended steps");
}

void FieldSteps::appendFile(const std::filesystem::path&) {
  throw Error("FieldTimeline: this series takes no appended steps");
}

void FieldTimeline::append(double time, std::shared_ptr<const VectorField> frame,
                           const std::filesystem::path& file) {
  if (!frame) throw Error("FieldTimeline: a missing frame");
  if (!(time > times_.back()))
    throw Error(concat("FieldTimeline: a frame at ", time, " s does not follow the last one's ",
                       times_.back(), " s"));
  if (steps_) {
    if (file.empty()) throw Error("FieldTimeline: a streamed series' new step needs its file");
    steps_->append(file, std::move(frame));  // checks the grid
    times_.push_back(time);
    return;
  }
  const VectorField& first = *frames_[0];
  if (const std::string difference = gridDifference(*frame, first); !difference.empty())
    throw Error(concat("the step at ", time, " s has ", difference,
                       "; expected every step on the same grid"));
  times_.push_back(time);
  frames_.push_back(std::move(frame));
}

FieldTimeline::Position FieldTimeline::at(double t, bool loop) const {
  const std::size_t n = times_.size();
  if (n == 1) return {0, 0, 0.0f};
  const double start = times_.front(), end = times_.back();
  if (loop) {
    // One period holds every frame and the step from the last back to the first,
    // which takes as long as the average step.
    const double period = (end - start) * double(n) / double(n - 1);
    double u = std::fmod(t - start, period);
    if (u < 0) u += period;
    t = start + u;
    if (t >= end) return {n - 1, 0, float((t - end) / (period - (end - start)))};
  }
  if (t <= start) return {0, 1, 0.0f};  // frame 0, already paired with the next one
  if (t >= end) return {n - 1, n - 1, 0.0f};
  const std::size_t b =
      std::size_t(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin());
  const std::size_t a = b - 1;
  return {a, b, float((t - times_[a]) / (times_[b] - times_[a]))};
}

void FieldTimeline::readAhead(const Position& at, bool backwards, bool loop) const {
  if (!steps_) return;
  steps_->want(aheadOrder(times_.size(), steps_->capacity(), at, backwards, loop));
}

std::optional<std::size_t> FieldTimeline::upcomingIndex(std::size_t n, const Position& at,
                                                        bool backwards, bool loop) {
  if (at.first >= n || at.second >= n) return std::nullopt;
  std::size_t i = 0;
  if (backwards) {
    if (at.first == 0 && !loop) return std::nullopt;
    i = at.first == 0 ? n - 1 : at.first - 1;
  } else {
    if (at.second + 1 == n && !loop) return std::nullopt;
    i = (at.second + 1) % n;
  }
  if (i == at.first || i == at.second) return std::nullopt;  // already in use (a short series)
  return i;
}

std::vector<std::size_t> FieldTimeline::aheadOrder(std::size_t n, std::size_t count,
                                                   const Position& at, bool backwards, bool loop) {
  count = std::min(count, n);
  std::vector<std::size_t> order;
  const auto add = [&](std::size_t i) {
    if (std::find(order.begin(), order.end(), i) == order.end()) order.push_back(i);
  };
  add(at.first);
  add(at.second);
  // Onwards from the pair in the direction of play.
  std::size_t i = backwards ? at.first : at.second;
  for (std::size_t tries = 0; order.size() < count && tries < n; ++tries) {
    if (backwards) {
      if (i == 0 && !loop) break;
      i = i == 0 ? n - 1 : i - 1;
    } else {
      if (i + 1 == n && !loop) break;
      i = i + 1 == n ? 0 : i + 1;
    }
    add(i);
  }
  order.resize(std::min(order.size(), count));
  return order;
}

}  // namespace sandstorm
