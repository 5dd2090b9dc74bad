#include "core/sim/main_context.h"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "core/color/color_grid.h"
#include "core/sim/emission.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

// Which colour grid the state asks of the update's field (colorGridName).
std::optional<std::string> wantedColorGrid(const ParticleState& state, const FieldUpdate& update) {
  if (!update.field) return std::nullopt;
  return colorGridName(state.render.colorBy, state.render.colorArray, *update.field);
}

// Every field the main context sends carries its range (the colour scale's
// default ends), computed here once rather than on every wall, and, while
// particles are coloured by one, its colour grid (a grid the size of the
// field's: vorticity or a scalar array of the file).
// `known`: a sparse grid's speed and velocity range, when computed already
// for this very grid (only its colour grid changes).
FieldUpdate withRange(FieldUpdate update, const ParticleState& state,
                      const FieldRange* known = nullptr) {
  if (!update.field) return update;
  update.colorGrid.reset();
  update.nextColorGrid.reset();
  update.colorArray.clear();
  if (const std::optional<std::string> name = wantedColorGrid(state, update)) {
    update.colorGrid = makeColorGrid(*update.field, *name);
    if (update.next) update.nextColorGrid = makeColorGrid(*update.next, *name);
    // A time-varying file whose next frame lacks the array: blend nothing.
    if (update.next && !update.nextColorGrid) update.colorGrid.reset();
    if (update.colorGrid) update.colorArray = *name;
  }
  update.range = FieldRange::of(*update.field, update.placement.rotation, update.colorGrid.get());
  if (update.sparse) {
    // The speeds the particles meet are the sparse grid's, not its overview's.
    FieldRange r = known ? *known : FieldRange::of(*update.sparse, update.placement.rotation);
    r.minScalar = update.range.minScalar;
    r.maxScalar = update.range.maxScalar;
    update.range = r;
  }
  return update;
}

// The colour grid the update carries, in colorGridName's terms.
std::optional<std::string> carriedColorGrid(const FieldUpdate& update) {
  return update.colorGrid ? std::optional<std::string>(update.colorArray) : std::nullopt;
}

}  // namespace

MainContext::MainContext(ParticleState initial, FieldUpdate field, Options options)
    : initial_(initial),
      options_(options),
      state_(initial),
      pending_(std::move(initial)),
      field_(std::make_shared<const FieldUpdate>(withRange(std::move(field), state_))) {}

AttributeResult MainContext::set(std::string_view key, const AttributeValue& value) {
  const AttributeTable& table = AttributeTable::instance();
  std::lock_guard lock(mutex_);
  ParticleState trial = pending_;
  AttributeResult result = table.set(trial, key, value);  // throws before anything changes
  const std::string canonical = table.canonical(key);
  if (canonical == "sim.maximum" && std::size_t(trial.sim.maximum) > options_.capacityLimit) {
    trial.sim.maximum = int(options_.capacityLimit);
    result.applied = trial.sim.maximum;
    result.warning = concat("sim.maximum: ", toString(value),
                            " exceeds the particle buffers' limit (run.capacity_limit = ",
                            options_.capacityLimit, "); capped to ", options_.capacityLimit);
  }
  // Colouring by an array the field does not carry is refused, naming those it does.
  if ((canonical == "render.color_by" || canonical == "render.color_array") &&
      trial.render.colorBy == ColorQuantity::Array && field_ && field_->field &&
      !wantedColorGrid(trial, *field_))
    throw Error(trial.render.colorArray.empty()
                    ? std::string("render.color_by: array: the field carries no scalar array")
                    : concat("render.color_array: the field has no scalar array '",
                             trial.render.colorArray,
                             "'; its arrays: ", field_->field->scalarNames()));
  if (!result.warning.empty()) log::warn(result.warning);
  const StateChange change = StateChange::set(canonical, result.applied);
  pending_ = std::move(trial);
  queued_.push_back(change);
  return result;
}

AttributeResult MainContext::setFromText(std::string_view key, std::string_view text) {
  return set(key, AttributeTable::instance().parse(key, text));
}

void MainContext::addEmitter(const Emitter& emitter) {
  enqueue(StateChange::addEmitter(emitter));
}

void MainContext::removeEmitter(int index) {
  enqueue(StateChange::removeEmitter(index));
}

void MainContext::enqueue(const StateChange& change) {
  std::lock_guard lock(mutex_);
  ParticleState trial = pending_;
  applyChange(trial, change);  // throws for a change that does not fit
  pending_ = std::move(trial);
  queued_.push_back(change);
}

void MainContext::setField(FieldUpdate field) {
  std::lock_guard lock(mutex_);
  field_ = std::make_shared<const FieldUpdate>(withRange(std::move(field), state_));
  player_.reset();
  fieldChanged_ = true;
}

void MainContext::setFieldTimeline(FieldTimeline timeline, const FieldPlacement& placement) {
  const bool loop = state().field.loop;
  FieldPlayer player(std::move(timeline), placement, loop);  // waits for its first pair
  std::lock_guard lock(mutex_);
  player_.emplace(std::move(player));
  if (waitListener_) player_->setWaitListener(waitListener_);
  if (replayWaits_) player_->replayWaits(*replayWaits_);
  const FieldPlayer::Frame now = player_->current();
  field_ =
      std::make_shared<const FieldUpdate>(withRange(FieldUpdate{.field = now.field,
                                                                .placement = placement,
                                                                .next = now.next,
                                                                .series = player_->seriesRef()},
                                                    state_));
  fieldChanged_ = true;
}

void MainContext::appendFieldFrame(double time, std::shared_ptr<const VectorField> frame,
                                   const std::filesystem::path& file) {
  std::lock_guard lock(mutex_);
  if (!player_) throw Error("appendFieldFrame: the field is not time-varying");
  player_->append(time, std::move(frame), file);
}

std::size_t MainContext::fieldFrames() const {
  std::lock_guard lock(mutex_);
  return player_ ? player_->size() : 1;
}

FieldPlaybackStatus MainContext::fieldStatus() const {
  std::lock_guard lock(mutex_);
  return player_ ? player_->status() : FieldPlaybackStatus{};
}

void MainContext::setFieldWaitListener(FieldPlayer::WaitListener listener) {
  std::lock_guard lock(mutex_);
  waitListener_ = std::move(listener);
  if (player_) player_->setWaitListener(waitListener_);
}

void MainContext::replayFieldWaits(std::set<std::uint32_t> frames) {
  std::lock_guard lock(mutex_);
  replayWaits_ = std::move(frames);
  if (player_) player_->replayWaits(*replayWaits_);
}

void MainContext::reset() {
  enqueue(StateChange::reset());
}

void MainContext::setViewer(const Viewer& viewer) {
  std::lock_guard lock(mutex_);
  viewer_ = viewer;
}

void MainContext::setTracking(const TrackingSample& sample, const WandRay& wand) {
  std::lock_guard lock(mutex_);
  tracking_ = sample;
  wand_ = wand;
}

void MainContext::reportFrameTime(double ms) {
  std::lock_guard lock(mutex_);
  reportedFrameMs_ = ms;
}

double MainContext::time() const {
  std::lock_guard lock(mutex_);
  return time_;
}

void MainContext::schedule(std::uint32_t frame, const StateChange& change) {
  std::lock_guard lock(mutex_);
  scheduled_.emplace(frame, change);
}

FramePacket MainContext::next() {
  // The clock is read here and only here.
  float dt = options_.fixedDt;
  if (dt <= 0.0f) {
    const auto now = std::chrono::steady_clock::now();
    dt = lastTick_ ? std::chrono::duration<float>(now - *lastTick_).count() : 1.0f / 60.0f;
    lastTick_ = now;
    dt = std::clamp(dt, 0.0f, options_.maxDt);
  }

  const auto now = std::chrono::steady_clock::now();
  std::optional<double> measuredMs;
  if (lastFrame_) measuredMs = std::chrono::duration<double, std::milli>(now - *lastFrame_).count();
  lastFrame_ = now;

  std::lock_guard lock(mutex_);
  FramePacket packet;
  packet.frame = frame_;
  packet.dt = dt;
  packet.seed = options_.seed;
  packet.time = time_;
  packet.viewer = viewer_;
  packet.tracking = tracking_;
  packet.wand = wand_;
  time_ += dt;

  // Scheduled changes for this frame (or overdue) come first, then live requests.
  std::vector<StateChange> due;
  for (auto it = scheduled_.begin(); it != scheduled_.end() && it->first <= frame_;)
    due.push_back(it->second), it = scheduled_.erase(it);
  due.insert(due.end(), queued_.begin(), queued_.end());
  queued_.clear();
  // Only changes that apply here travel, so walls see exactly what the main context did.
  for (StateChange& change : due) {
    try {
      applyChange(state_, change);
    } catch (const Error& e) {
      log::error("frame ", frame_, ": ", e.what(), "; change dropped");
      continue;
    }
    if (listener_) listener_(frame_, change);
    if (change.kind == StateChange::Kind::Reset) packet.reset = true;
    packet.changes.push_back(std::move(change));
  }
  pending_ = state_;

  packet.simDt = state_.sim.paused ? 0.0f : dt * state_.sim.timeScale;
  packet.simTime = simTime_;
  simTime_ += double(packet.simDt);
  if (player_) {
    // The field's clock runs on simulated time, at the playback speed (FieldPlayer).
    const FieldPlayer::Frame now = player_->advance(frame_, state_.field, double(packet.simDt));
    if (now.changed) {
      field_ = std::make_shared<const FieldUpdate>(
          withRange(FieldUpdate{.field = now.field,
                                .placement = player_->placement(),
                                .next = now.next,
                                .series = player_->seriesRef()},
                    state_));
      fieldChanged_ = true;
    }
    // The pair named as playback reads ahead now (the first pair was named
    // before the first frame set the direction of play).
    if (fieldChanged_ && field_ && field_->series && field_->series != player_->seriesRef()) {
      FieldUpdate named = *field_;
      named.series = player_->seriesRef();
      field_ = std::make_shared<const FieldUpdate>(std::move(named));
    }
    packet.fieldBlend = now.weight;
    if (options_.uploadAhead) packet.upcomingField = player_->upcoming();
  }
  // Coloured by another grid now (or no longer): the field goes again with it.
  if (field_ && field_->field && carriedColorGrid(*field_) != wantedColorGrid(state_, *field_)) {
    field_ = std::make_shared<const FieldUpdate>(withRange(*field_, state_, &field_->range));
    fieldChanged_ = true;
  }
  // A field without the array asked for (a file switched, a config's choice):
  // particles take the scale's low end; say so once.
  const bool missing = field_ && field_->field && state_.render.colorBy == ColorQuantity::Array &&
                       !field_->colorGrid;
  if (missing && !warnedMissingArray_)
    log::warn("render.color_array: the field has no scalar array",
              state_.render.colorArray.empty() ? "" : " '" + state_.render.colorArray + "'",
              "; its arrays: ", field_->field->scalarNames(),
              ". Particles take the colour scale's low end");
  warnedMissingArray_ = missing;
  if (fieldChanged_) packet.fieldUpdate = field_;
  fieldChanged_ = false;

  // Level of detail: the rates scaled before Reeves' draw, here and only here.
  const float coverage = field_ && field_->field
                             ? viewCoverage(field_->field->bounds(), field_->placement, viewer_)
                             : 1.0f;
  packet.lodScale =
      lod_.update(state_.sim, coverage, reportedFrameMs_ ? reportedFrameMs_ : measuredMs);
  if (packet.lodScale < 1.0f) {
    ParticleState scaled = state_;
    for (Emitter& e : scaled.emitters) {
      e.rate *= packet.lodScale;
      e.rateVariance *= packet.lodScale;
    }
    packet.emission = emissionCounts(scaled, packet.simDt, Seed::from(options_.seed), frame_);
  } else {
    packet.emission = emissionCounts(state_, packet.simDt, Seed::from(options_.seed), frame_);
  }
  ++frame_;
  return packet;
}

ParticleState MainContext::state() const {
  std::lock_guard lock(mutex_);
  return state_;
}

ParticleState MainContext::pendingState() const {
  std::lock_guard lock(mutex_);
  return pending_;
}

std::uint32_t MainContext::nextFrame() const {
  std::lock_guard lock(mutex_);
  return frame_;
}

std::shared_ptr<const FieldUpdate> MainContext::field() const {
  std::lock_guard lock(mutex_);
  return field_;
}

void MainContext::setChangeListener(ChangeListener listener) {
  std::lock_guard lock(mutex_);
  listener_ = std::move(listener);
}

}  // namespace sandstorm
