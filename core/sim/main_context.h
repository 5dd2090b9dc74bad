// MainContext: the one owner of everything that must be the same on every wall
// (split first, thesis 5.3): the particle state and its table of dynamic
// attributes, the emitters, the vector field, the random seed and the clock.
//
// Each frame, next() produces one FramePacket. Requests (set, addEmitter, ...)
// are validated when made, against the state as it will be once earlier
// requests have taken effect, and take effect together at the next packet's
// frame, or at a frame given explicitly (for scripted runs and replays).
// Requests are thread-safe; next() is called by one thread, the frame loop.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string_view>
#include <vector>

#include "core/field/field_timeline.h"
#include "core/sim/attribute_table.h"
#include "core/sim/field_player.h"
#include "core/sim/frame_packet.h"
#include "core/sim/level_of_detail.h"
#include "core/sim/particle_state.h"

namespace sandstorm {

class MainContext {
 public:
  struct Options {
    std::uint64_t seed = 1;
    float fixedDt = 0.0f;  // > 0: every frame advances this much; 0: measure the clock
    float maxDt = 0.1f;    // a measured frame longer than this (a stall) counts as this
    std::size_t capacityLimit =
        1u << 26;             // sim.maximum beyond this is capped (the buffers can grow no further)
    bool uploadAhead = true;  // packets name a series' coming step (FramePacket::upcomingField)
  };

  // Called for every change with the frame it takes effect (the session recorder).
  using ChangeListener = std::function<void(std::uint32_t frame, const StateChange&)>;

  MainContext(ParticleState initial, FieldUpdate field, Options options);

  // The state the walls start from (before packet 0); walls are built from it.
  const ParticleState& initialState() const { return initial_; }

  AttributeResult set(std::string_view key, const AttributeValue& value);
  AttributeResult setFromText(std::string_view key, std::string_view text);
  void addEmitter(const Emitter& emitter);
  void removeEmitter(int index);
  void setField(FieldUpdate field);
  // A time-varying field: played by the field.* attributes (speed, loop,
  // pause; FieldPlayer). Waits for a streamed timeline's first pair; throws
  // Error when it cannot be read.
  void setFieldTimeline(FieldTimeline timeline, const FieldPlacement& placement);
  // A new last frame of the time-varying field (a step a running simulation
  // wrote, FieldStream); with field.follow the field jumps to it at the next
  // packet. Throws Error, changing nothing, when there is no timeline or the
  // frame does not fit it (FieldTimeline::append).
  // `file`: where the frame was read from (a streamed timeline reads it again when wanted).
  void appendFieldFrame(double time, std::shared_ptr<const VectorField> frame,
                        const std::filesystem::path& file = {});
  // The time-varying field's frames (1 for a still field) and the newest's time.
  std::size_t fieldFrames() const;
  // Where a time-varying field's playback stands (for the menu).
  FieldPlaybackStatus fieldStatus() const;
  // Called at every frame a streamed field's playback waited for the disk (the recorder).
  void setFieldWaitListener(FieldPlayer::WaitListener listener);
  // Replaying a recorded run: playback waits at exactly these frames (FieldPlayer),
  // of this and any later time-varying field.
  void replayFieldWaits(std::set<std::uint32_t> frames);
  void reset();
  // The head and navigation the next packets carry (the app samples its trackers).
  void setViewer(const Viewer& viewer);
  // The tracked head and wand and the wand's ray the next packets carry.
  void setTracking(const TrackingSample& sample, const WandRay& wand);
  // How long the last frame took, for the level of detail's budget (the app
  // may report its slowest wall); without reports, the interval between
  // next() calls, which the slowest wall paces through the FrameChannel.
  void reportFrameTime(double ms);
  double time() const;
  // A validated change that takes effect at `frame` (or the next frame if that has passed).
  void schedule(std::uint32_t frame, const StateChange& change);

  FramePacket next();

  // The state as of the last packet, and as it will be after pending requests.
  ParticleState state() const;
  ParticleState pendingState() const;
  std::uint32_t nextFrame() const;
  std::uint64_t seed() const { return options_.seed; }
  std::shared_ptr<const FieldUpdate> field() const;

  void setChangeListener(ChangeListener listener);

 private:
  void enqueue(const StateChange& change);

  const ParticleState initial_;
  const Options options_;
  mutable std::mutex mutex_;
  ParticleState state_;    // as of the last packet
  ParticleState pending_;  // with every queued change applied
  std::vector<StateChange> queued_;
  std::multimap<std::uint32_t, StateChange> scheduled_;
  std::shared_ptr<const FieldUpdate> field_;
  std::optional<FieldPlayer> player_;
  FieldPlayer::WaitListener waitListener_;
  std::optional<std::set<std::uint32_t>> replayWaits_;
  bool fieldChanged_ = true;  // packet 0 always carries the field
  bool warnedMissingArray_ = false;
  std::uint32_t frame_ = 0;
  double time_ = 0.0;
  double simTime_ = 0.0;  // simulated seconds so far
  Viewer viewer_;
  TrackingSample tracking_;
  WandRay wand_;
  LevelOfDetail lod_;
  std::optional<double> reportedFrameMs_;
  std::optional<std::chrono::steady_clock::time_point> lastFrame_;
  std::optional<std::chrono::steady_clock::time_point> lastTick_;
  ChangeListener listener_;
};

}  // namespace sandstorm
