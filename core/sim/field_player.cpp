#include "core/sim/field_player.h"

#include <algorithm>

#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {

FieldPlayer::FieldPlayer(FieldTimeline timeline, const FieldPlacement& placement, bool loop)
    : timeline_(std::move(timeline)), placement_(placement) {
  time_ = timeline_.time(0);
  loop_ = loop;
  position_ = timeline_.at(time_, loop);
  timeline_.readAhead(position_, false, loop);
  field_ = timeline_.wait(position_.first);  // without it there is nothing to show: throws
  try {
    next_ = timeline_.wait(position_.second);
  } catch (const Error& e) {
    // The second step does not read: the first alone, and playback stopped there.
    error_ = e.what();
    log::error("field: ", error_, "; playback stops at the first step and the run goes on");
    next_ = field_;
    position_.second = position_.first;
  }
}

FieldPlayer::Frame FieldPlayer::current() const {
  return Frame{false, field_, next_, position_.weight};
}

std::shared_ptr<const VectorField> FieldPlayer::upcoming() const {
  if (!error_.empty()) return nullptr;
  const std::optional<std::size_t> i =
      FieldTimeline::upcomingIndex(timeline_.size(), position_, backwards_, loop_);
  return i ? timeline_.frame(*i) : nullptr;
}

std::optional<FieldSeriesRef> FieldPlayer::seriesRef() const {
  const FieldSteps* steps = timeline_.steps().get();
  if (!steps) return std::nullopt;
  return FieldSeriesRef{.steps = std::uint32_t(timeline_.size()),
                        .first = std::uint32_t(position_.first),
                        .second = std::uint32_t(position_.second),
                        .firstFile = steps->identity(position_.first),
                        .secondFile = steps->identity(position_.second),
                        .backwards = backwards_,
                        .loop = loop_};
}

void FieldPlayer::append(double time, std::shared_ptr<const VectorField> frame,
                         const std::filesystem::path& file) {
  timeline_.append(time, std::move(frame), file);
  // The pair in use may now blend towards the new frame: look again at the next packet.
  position_ = {timeline_.size(), timeline_.size(), position_.weight};
}

void FieldPlayer::replayWaits(std::set<std::uint32_t> frames) {
  replayWaits_ = std::move(frames);
}

bool FieldPlayer::fetch(std::uint32_t frame, const FieldTimeline::Position& at, Frame& out) {
  if (!error_.empty()) return false;  // stopped at the last pair read
  const bool replaying = replayWaits_.has_value();
  if (replaying && replayWaits_->count(frame)) return false;
  try {
    out.field = replaying ? timeline_.wait(at.first) : timeline_.frame(at.first);
    out.next = replaying ? timeline_.wait(at.second) : timeline_.frame(at.second);
  } catch (const Error& e) {
    error_ = e.what();
  }
  if (timeline_.streamed() && error_.empty() && (!out.field || !out.next)) {
    const std::size_t missing = out.field ? at.second : at.first;
    const std::string failure = timeline_.steps()->failure(missing);
    if (!failure.empty()) error_ = failure;
  }
  if (!error_.empty()) {
    const std::size_t last = timeline_.size() - 1;
    log::error("field: ", error_, "; playback stops at the last pair read (t = ",
               timeline_.time(std::min(position_.first, last)), " to ",
               timeline_.time(std::min(position_.second, last)), " s) and the run goes on");
    waitingFor_.clear();
    return false;
  }
  return out.field && out.next;
}

FieldPlayer::Frame FieldPlayer::advance(std::uint32_t frame, const FieldPlayback& playback,
                                        double simDt) {
  backwards_ = playback.speed < 0.0f;
  loop_ = playback.loop;
  if (playback.follow) time_ = timeline_.time(timeline_.size() - 1);
  const FieldTimeline::Position at = timeline_.at(time_, playback.loop);
  timeline_.readAhead(at, playback.speed < 0.0f, playback.loop);
  Frame out{false, field_, next_, at.weight};
  if (at.first != position_.first || at.second != position_.second) {
    Frame fetched;
    if (!fetch(frame, at, fetched)) {
      // Wait: the clock stands, the walls keep the pair (and weight) they have.
      if (error_.empty()) {
        const std::size_t missing = timeline_.frame(at.first) ? at.second : at.first;
        if (waitingFor_.empty()) {
          waitingFor_ = timeline_.streamed() ? timeline_.steps()->name(missing) : "";
          waitStart_ = frame;
          log::warn("field: playback waits for ", waitingFor_,
                    " to be read (the disk is slower than playback; field.read_ahead reads "
                    "further ahead, field.speed plays slower)");
        }
      }
      if (error_.empty()) {
        ++framesWaited_;
        if (listener_) listener_(frame);
      }
      return Frame{false, field_, next_, position_.weight};
    }
    if (!waitingFor_.empty())
      log::info("field: ", waitingFor_, " read after ", frame - waitStart_,
                " frames of waiting; playback goes on");
    waitingFor_.clear();
    field_ = fetched.field;
    next_ = fetched.next;
    out = Frame{true, field_, next_, at.weight};
  }
  position_ = at;
  if (!playback.paused) time_ += simDt * double(playback.speed);
  return out;
}

FieldPlaybackStatus FieldPlayer::status() const {
  FieldPlaybackStatus s;
  s.steps = timeline_.size();
  s.first = position_.first;
  s.second = position_.second;
  s.time = time_;
  s.streamed = timeline_.streamed();
  if (s.streamed) s.resident = timeline_.steps()->resident();
  s.waitingFor = waitingFor_;
  s.error = error_;
  s.framesWaited = framesWaited_;
  return s;
}

}  // namespace sandstorm
