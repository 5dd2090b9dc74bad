#include "app/tracking/tracking_input.h"

#include "app/tracking/dtrack_receiver.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {

bool TrackingInput::wanted(const TrackingSpec& tracking,
                           const std::vector<ScheduledTracking>& replayed) {
  return tracking.source != TrackingSource::None || !replayed.empty();
}

TrackingInput::TrackingInput(const TrackingSpec& tracking, const NavigationSpec& navigation,
                             std::vector<ScheduledTracking> replayed,
                             std::unique_ptr<TrackerSource> source)
    : source_(std::move(source)),
      sampler_(tracking),
      wand_(tracking, navigation),
      replayed_(std::move(replayed)) {
  if (!replayed_.empty()) {
    if (tracking.source == TrackingSource::DTrack)
      log::info("tracking: replaying the session's recorded tracking; UDP port ", tracking.port,
                " stays closed");
    return;
  }
  if (tracking.source == TrackingSource::Replay)
    throw Error(concat("tracking.source = \"replay\" (line ", tracking.line,
                       "): expected --replay FILE with a session recorded with tracking "
                       "(its 'track' lines)"));
  if (tracking.source == TrackingSource::DTrack && !source_)
    source_ = std::make_unique<DTrackReceiver>(
        DTrackReceiver::Options{.port = tracking.port,
                                .multicast = tracking.multicast,
                                .senders = tracking.senders,
                                .interfaceAddress = tracking.interfaceAddress});
}

TrackingSample TrackingInput::sample(std::uint32_t frame) {
  if (replaying()) {
    // Recorded only when it changed: the last sample at or before this frame holds.
    while (replayAt_ < replayed_.size() && replayed_[replayAt_].frame <= frame)
      last_ = replayed_[replayAt_++].sample;
    return last_;
  }
  const std::optional<TrackerMeasurement> newest = source_ ? source_->newest() : std::nullopt;
  last_ = sampler_.sample(newest ? &*newest : nullptr, steadySeconds());
  return last_;
}

WandActions TrackingInput::wand(const TrackingSample& sample, const WandScene& scene, float dt) {
  return wand_.update(sample, scene, dt);
}

TrackingStatus TrackingInput::status() const {
  TrackingStatus s;
  s.source = replaying() ? std::string("the replayed session")
                         : (source_ ? source_->describe() : std::string("none"));
  if (source_) s.stats = source_->stats();
  s.waiting = !last_.active;
  s.lost = last_.stale;
  s.trackerFrame = last_.trackerFrame;
  s.wandPresent = last_.wand.present;
  s.wandTracked = last_.wand.tracked;
  return s;
}

}  // namespace sandstorm
