#include "core/tracking/tracking_sampler.h"

#include "core/util/log.h"

namespace sandstorm {

TrackingSampler::TrackingSampler(const TrackingSpec& spec) : spec_(spec), calibration_(spec) {}

TrackingSample TrackingSampler::sample(const TrackerMeasurement* newest, double now) {
  if (newest && (!any_ || newest->sequence != lastSequence_)) {
    any_ = true;
    lastSequence_ = newest->sequence;
    const TrackerFrame& f = newest->frame;
    held_.trackerFrame = f.frame.value_or(std::uint32_t(newest->sequence));
    if (const std::optional<TrackedPose> head = calibration_.head(f)) {
      held_.head = *head;
      haveHead_ = true;
      headSeconds_ = newest->arrivalSeconds;
    }
    if (const std::optional<WandSample> wand = calibration_.wand(f)) {
      flystickSeconds_ = newest->arrivalSeconds;
      held_.wand.present = true;
      held_.wand.buttons = wand->buttons;
      held_.wand.joystick = wand->joystick;
      // DTrack's own word that the wand is untracked counts at once: only a
      // measurement that is missing (no datagram) holds the last pose.
      haveWand_ = wand->tracked;
      if (wand->tracked) {
        held_.wand.pose = wand->pose;
        wandSeconds_ = newest->arrivalSeconds;
      }
    }
  }
  const double stale = double(spec_.staleMs) * 1e-3;
  TrackingSample s = held_;
  s.active = any_;
  s.headTracked = haveHead_;
  s.stale = any_ && (!haveHead_ || now - headSeconds_ > stale);
  s.wand.tracked = haveWand_ && now - wandSeconds_ <= stale;
  if (s.wand.present && now - flystickSeconds_ > stale) {
    s.wand.present = false;  // the radio went quiet too: no button stays held
    s.wand.buttons = 0;
  }
  if (!s.wand.present) s.wand.joystick = glm::vec2(0.0f);  // a quiet radio: no flying
  if (s.stale && !lost_)
    log::warn("tracking lost: no measurement of head body ", spec_.headBody, " for more than ",
              spec_.staleMs, " ms; holding the last pose");
  if (!s.stale && lost_) log::info("tracking resumed");
  lost_ = s.stale;
  return s;
}

}  // namespace sandstorm
