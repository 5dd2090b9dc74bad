#include "core/util/progress_meter.h"

#include <cstdio>

#include "core/util/log.h"

namespace sandstorm {
namespace {

std::int64_t nanoseconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(d).count();
}

}  // namespace

ProgressMeter::ProgressMeter(std::string what, std::uint64_t total, std::string unit)
    : what_(std::move(what)),
      unit_(std::move(unit)),
      total_(total),
      start_(Clock::now()),
      nextReportNs_(1'000'000'000) {
  ProgressBoard::instance().add(this);
}

ProgressMeter::~ProgressMeter() {
  ProgressBoard::instance().remove(this);
}

ProgressSnapshot ProgressMeter::snapshot() const {
  ProgressSnapshot s;
  s.what = what_;
  s.unit = unit_;
  s.done = done_.load(std::memory_order_relaxed);
  s.total = total_;
  s.seconds = std::chrono::duration<double>(Clock::now() - start_).count();
  s.rate = s.seconds > 0.0 ? double(s.done) / s.seconds : 0.0;
  s.secondsLeft =
      s.rate > 0.0 && total_ > 0 ? double(total_ - std::min(s.done, total_)) / s.rate : 0.0;
  return s;
}

void ProgressMeter::add(std::uint64_t done) {
  done_.fetch_add(done, std::memory_order_relaxed);
  const Clock::time_point t = Clock::now();
  if (nanoseconds(t - start_) < nextReportNs_.load(std::memory_order_relaxed)) return;
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  report(t);
}

void ProgressMeter::report(Clock::time_point now) {
  nextReportNs_.store(nanoseconds(now - start_) + 1'000'000'000, std::memory_order_relaxed);
  log::info(snapshot().text());
  said_ = true;
}

void ProgressMeter::finish() {
  std::lock_guard lock(mutex_);
  if (!said_) return;
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.1f",
                std::chrono::duration<double>(Clock::now() - start_).count());
  log::info(what_, ": done, ", total_ ? total_ : done_.load(), " ", unit_, " in ", seconds, " s");
}

}  // namespace sandstorm
