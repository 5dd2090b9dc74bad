#include "app/stepped_run.h"

#include <algorithm>
#include <chrono>

#include "app/wall_lines.h"
#include "contexts/platform/software_rasterizer.h"
#include "core/util/error.h"

namespace sandstorm {

SteppedRun::SteppedRun(AppConfig config, AppOptions options, std::optional<FieldSource> field) {
  options.headless = true;
  if (!options.frames) options.frames = 0;  // as many as the caller steps
  app_ = std::make_unique<App>(std::move(config), std::move(options));
  keepSoftwareRasterizingInDrawingThreads(app_->config().glContexts());
  run_ = std::make_unique<AppRun>(app_->config(), app_->options(), true, nullptr, std::move(field));
  pending_.resize(app_->config().walls.size());
  captures_.resize(app_->config().walls.size());
  run_->setFrameObserver([this](std::size_t wall, WallRenderer& w, const FramePacket& packet) {
    {
      std::lock_guard lock(mutex_);
      if (std::int64_t(packet.frame) != captureAt_) return;
    }
    WallCapture c;
    c.frame = packet.frame;
    c.image = w.capture();
    c.particles = w.particles().update().readBack();
    if (w.particles().state().render.trailLength > 0) c.trails = w.particles().readBackTrails();
    c.state = w.particles().state();
    c.field = w.particles().field();
    c.fieldBlend = packet.fieldBlend;
    std::lock_guard lock(mutex_);
    pending_[wall] = std::move(c);
    captured_.notify_all();
  });
  if (!run_->start()) {
    close();
    throw Error("the run's walls could not open (the log says why)");
  }
}

SteppedRun::~SteppedRun() {
  close();
}

void SteppedRun::check() const {
  if (!run_) throw Error("this run is closed");
}

void SteppedRun::step(int n) {
  check();
  if (n < 1) throw Error(concat("step(n): n is ", n, "; expected 1 or more frames"));
  const std::int64_t target = run_->framesMade() + n - 1;
  {
    std::lock_guard lock(mutex_);
    captureAt_ = target;
    for (auto& p : pending_)
      p.reset();
  }
  auto wallError = [&]() -> std::optional<std::string> {
    for (const auto& w : run_->walls())
      if (auto e = w->error()) return concat("wall '", w->name(), "': ", *e);
    return std::nullopt;
  };
  for (int i = 0; i < n; ++i)
    if (!run_->advance()) {
      if (auto e = wallError()) throw Error(*e);
      throw Error(concat("the run stopped at frame ", run_->framesMade()));
    }
  std::unique_lock lock(mutex_);
  for (;;) {
    const bool all = std::ranges::all_of(pending_, [](const auto& p) { return p.has_value(); });
    if (all) break;
    captured_.wait_for(lock, std::chrono::milliseconds(50));
    lock.unlock();
    const auto e = wallError();
    lock.lock();
    if (e) throw Error(*e);
  }
  for (std::size_t w = 0; w < pending_.size(); ++w)
    captures_[w] = std::move(pending_[w]);
  captureAt_ = -1;
}

std::string SteppedRun::set(const std::string& key, const std::string& value) {
  check();
  return run_->mainContext().setFromText(key, value).warning;
}

int SteppedRun::frames() const {
  check();
  return run_->framesMade();
}

std::vector<std::string> SteppedRun::wallNames() const {
  check();
  std::vector<std::string> names;
  for (const auto& w : run_->walls())
    names.push_back(w->name());
  return names;
}

std::size_t SteppedRun::wallIndex(std::size_t index) const {
  check();
  if (index >= captures_.size())
    throw Error(concat("wall ", index, ": this run has ", captures_.size(), " wall(s)"));
  return index;
}

const WallCapture& SteppedRun::capture(std::size_t index) const {
  const auto& c = captures_[wallIndex(index)];
  if (!c) throw Error("no frame yet: step() the run first");
  return *c;
}

std::vector<Streamline> SteppedRun::streamlines(std::size_t index) const {
  const WallCapture& c = capture(index);
  return wallStreamlines(c.state, c.field, c.fieldBlend, run_->terrain().get());
}

std::vector<Streamline> SteppedRun::trails(std::size_t index,
                                           std::vector<std::size_t>& owners) const {
  const WallCapture& c = capture(index);
  return trailLines(c.particles, c.trails, owners);
}

WallStats SteppedRun::stats(std::size_t index) const {
  return run_->walls()[wallIndex(index)]->stats();
}

int SteppedRun::close() {
  if (run_) {
    exitCode_ = run_->stop();
    run_.reset();
    app_.reset();
  }
  return exitCode_;
}

}  // namespace sandstorm
