// FieldPlayer: the main context's clock for a time-varying field. Each frame
// it moves the field's time on (field.speed, loop, paused, follow), finds the
// two frames around it and the weight between them, and asks a streamed
// timeline to read the frames ahead.
//
// A streamed frame that is not read yet is waited for, never guessed: the
// field's clock stands still and the walls keep blending the pair they have,
// until the frame is in memory (said in the log and the menu). Walls and
// ranks all get the frames from the packets, so they agree whatever the disk
// does. Where playback waited is told to a listener (the session recorder);
// a replay is given those frames back and waits at exactly them, reading
// every other frame it needs before going on, so a streamed run replays
// frame for frame. A frame that cannot be read stops playback at the last
// pair read, with an error naming its file; the run goes on.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/field/field_placement.h"
#include "core/field/field_timeline.h"
#include "core/sim/sim_settings.h"

namespace sandstorm {

struct FieldPlaybackStatus {
  std::size_t steps = 1;              // frames in the timeline
  std::size_t first = 0, second = 0;  // the pair in use
  double time = 0.0;                  // the field's clock
  bool streamed = false;
  std::vector<std::size_t> resident;  // streamed frames in memory now
  std::string waitingFor;             // the frame's file playback waits for, or empty
  std::string error;                  // why playback stopped, or empty
  std::uint64_t framesWaited = 0;     // frames playback has waited for the disk
};

class FieldPlayer {
 public:
  struct Frame {
    bool changed = false;  // a new pair: field and next are to be sent
    std::shared_ptr<const VectorField> field, next;
    float weight = 0.0f;
  };
  using WaitListener = std::function<void(std::uint32_t frame)>;

  // Waits for the first pair (the start shows it). Throws Error when the
  // first step cannot be read; a second that cannot stops playback at the first.
  FieldPlayer(FieldTimeline timeline, const FieldPlacement& placement, bool loop);

  // The pair to show at `frame`, then the clock moved on by simDt * speed.
  Frame advance(std::uint32_t frame, const FieldPlayback& playback, double simDt);
  // The pair in use now.
  Frame current() const;
  // The frame after the pair in use in playback order (as the last advance
  // went: forwards or backwards, looping or not), if it is in memory; null
  // otherwise. What walls may upload ahead of need (FramePacket::upcomingField).
  std::shared_ptr<const VectorField> upcoming() const;
  // A streamed timeline's pair in use, named by step and file, and how
  // playback reads ahead (FieldUpdate::series); nullopt for frames in memory.
  std::optional<FieldSeriesRef> seriesRef() const;

  void append(double time, std::shared_ptr<const VectorField> frame,
              const std::filesystem::path& file = {});
  const FieldPlacement& placement() const { return placement_; }
  std::size_t size() const { return timeline_.size(); }
  FieldPlaybackStatus status() const;

  void setWaitListener(WaitListener listener) { listener_ = std::move(listener); }
  // Replaying: wait at exactly these frames, and read what is needed at any other.
  void replayWaits(std::set<std::uint32_t> frames);

 private:
  // The pair `at`, or false (playback waits) when it is not in memory.
  bool fetch(std::uint32_t frame, const FieldTimeline::Position& at, Frame& out);

  FieldTimeline timeline_;
  FieldPlacement placement_;
  double time_ = 0.0;
  bool backwards_ = false, loop_ = false;  // as the last advance played
  FieldTimeline::Position position_;
  std::shared_ptr<const VectorField> field_, next_;
  WaitListener listener_;
  std::optional<std::set<std::uint32_t>> replayWaits_;
  std::string waitingFor_, error_;
  std::uint32_t waitStart_ = 0;
  std::uint64_t framesWaited_ = 0;
};

}  // namespace sandstorm
