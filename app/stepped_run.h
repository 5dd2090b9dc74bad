// SteppedRun: the application run frame by frame by its caller (the Python
// module, app/python/). The configuration is settled as the command line
// settles it (App: --set, --walls, --record, --replay, --movie), every wall
// drawn offscreen; the walls keep their threads and GL contexts, so a stepped
// run computes what `sandstorm` computes, bit for bit. step(n) returns once
// every wall has drawn the n-th frame, and holds what each wall showed then:
// its picture (as --screenshot writes it), its particles (as
// --dump-particles), its trails, and its replica of the state and field for
// the streamlines. Not thread-safe: one thread drives it.
#pragma once

#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "app/app.h"
#include "app/app_run.h"
#include "core/flow/streamline_tracer.h"
#include "core/util/image.h"

namespace sandstorm {

struct WallCapture {
  std::uint32_t frame = 0;
  Image image;
  std::vector<Particle> particles;
  std::vector<std::vector<glm::vec3>> trails;  // newest first; none unless render.trail_length > 0
  ParticleState state;
  std::shared_ptr<const FieldUpdate> field;
  float fieldBlend = 0.0f;
};

class SteppedRun {
 public:
  // Opens the walls. Throws Error (the configuration's, a wall's).
  // `field`: the configuration's [field], already read (fileSceneField); empty: read here.
  SteppedRun(AppConfig config, AppOptions options, std::optional<FieldSource> field = std::nullopt);
  ~SteppedRun();
  SteppedRun(const SteppedRun&) = delete;
  SteppedRun& operator=(const SteppedRun&) = delete;

  // Runs n frames (n >= 1). Throws Error when the run cannot go on (a wall failed).
  void step(int n);
  // Sets an attribute from the next frame on, validated as --set is. Throws
  // Error naming the key; returns a warning when the value was clamped.
  std::string set(const std::string& key, const std::string& value);

  int frames() const;  // frames run so far
  std::vector<std::string> wallNames() const;
  // Wall `index`'s last frame; throws Error before the first step or for a wall it does not have.
  const WallCapture& capture(std::size_t index) const;
  std::vector<Streamline> streamlines(std::size_t index) const;
  std::vector<Streamline> trails(std::size_t index, std::vector<std::size_t>& owners) const;
  WallStats stats(std::size_t index) const;

  // Ends the run (the movie and recording are closed, the GL contexts freed).
  // Returns the run's exit code; later calls return it again.
  int close();
  bool closed() const { return !run_; }

 private:
  void check() const;
  std::size_t wallIndex(std::size_t index) const;

  std::unique_ptr<App> app_;
  std::unique_ptr<AppRun> run_;
  int exitCode_ = 0;

  std::mutex mutex_;
  std::condition_variable captured_;
  std::int64_t captureAt_ = -1;  // the frame whose pictures the walls keep
  std::vector<std::optional<WallCapture>> pending_, captures_;
};

}  // namespace sandstorm
