// FieldTimeline: a time-varying field as the main context plays it: frames
// (shared, never copied per wall) at increasing times, and for any playback
// time the two frames around it and the weight between them. The walls blend
// the two frames themselves (field + (next - field) * weight), so a frame
// travels to them once, when it comes into use, and only the weight travels
// every frame.
//
// Frames are held in memory (a field stream's steps, tests), or streamed:
// FieldSteps reads them on demand (core/io/series_reader.h) and keeps only
// the few around the playback time, so a series of any length plays in the
// memory of a handful of steps. A streamed frame may not be read yet:
// frame() is then null and the main context's playback waits for it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/field/vector_field.h"
#include "core/util/file_identity.h"

namespace sandstorm {

// Frames read on demand. Thread-safe.
class FieldSteps {
 public:
  virtual ~FieldSteps() = default;
  // The steps wanted next, most urgent first (at most capacity()); steps not
  // listed may be dropped from memory, listed ones are read in this order.
  virtual void want(const std::vector<std::size_t>& order) = 0;
  // Step i if it is in memory, null otherwise (never blocks).
  virtual std::shared_ptr<const VectorField> get(std::size_t i) = 0;
  // Step i, read now if it has to be. Throws Error naming its file when it cannot be read.
  virtual std::shared_ptr<const VectorField> wait(std::size_t i) = 0;
  // Why step i could not be read (its file and the error), or empty.
  virtual std::string failure(std::size_t i) const = 0;
  // The step's file, for messages.
  virtual std::string name(std::size_t i) const = 0;
  // How many steps may be in memory at once (>= 2: the two being blended).
  virtual std::size_t capacity() const = 0;
  // The steps in memory now, ascending (for the menu's loaded range).
  virtual std::vector<std::size_t> resident() const = 0;
  // Step i's file as it was when the series was opened (cluster ranks that
  // read the steps themselves check it against rank 0's); not `present` when
  // the steps have no files.
  virtual FileIdentity identity(std::size_t) const { return {}; }
  // A new last step (a watched folder's, FieldStream), read already from
  // `file`: held while wanted, read again from the file when wanted later.
  // Throws Error, changing nothing, when the steps take no new ones or the
  // frame is on another grid.
  virtual void append(const std::filesystem::path& file, std::shared_ptr<const VectorField> frame);
  // A new last step not read yet (a cluster rank following rank 0's watched
  // folder): read from `file` when wanted, and checked then. Throws Error when
  // the steps take no new ones.
  virtual void appendFile(const std::filesystem::path& file);
  // How many steps there are.
  virtual std::size_t size() const = 0;
};

// The pair a streamed timeline's playback is at, named so that another
// process holding the same series (a cluster rank) can take the same steps
// from its own reader and read ahead as playback does.
struct FieldSeriesRef {
  std::uint32_t steps = 0;               // in the series
  std::uint32_t first = 0, second = 0;   // the pair: the update's `field` and `next`
  FileIdentity firstFile, secondFile;    // their files as rank 0 opened them
  bool backwards = false, loop = false;  // how playback reads ahead from the pair

  bool operator==(const FieldSeriesRef&) const = default;
};

class FieldTimeline {
 public:
  struct Position {
    std::size_t first = 0, second = 0;
    float weight = 0.0f;  // towards `second`
  };

  // Frames held in memory. Throws Error unless there are frames, times
  // increase, and every frame shares the first one's dims and bounds.
  FieldTimeline(std::vector<double> times, std::vector<std::shared_ptr<const VectorField>> frames);
  // Frames streamed by `steps` (which checks each one's grid as it reads it).
  FieldTimeline(std::vector<double> times, std::shared_ptr<FieldSteps> steps);

  // Before the start: the first frame; past the end: the last, or with `loop`
  // wrapped into [start, end) (the last frame blends back into the first).
  Position at(double time, bool loop) const;

  // A new last frame (a simulation's next step, FieldStream): throws Error,
  // changing nothing, unless it follows the last frame's time and shares its
  // grid. A streamed timeline hands it to its steps with its `file`, which
  // keep it only while playback wants it, so memory stays flat however many
  // steps the simulation writes.
  void append(double time, std::shared_ptr<const VectorField> frame,
              const std::filesystem::path& file = {});

  std::size_t size() const { return times_.size(); }
  double time(std::size_t i) const { return times_[i]; }
  bool streamed() const { return steps_ != nullptr; }
  // Frame i, or null while a streamed frame is not read yet.
  std::shared_ptr<const VectorField> frame(std::size_t i) const;
  // Frame i, waiting for a streamed one to be read. Throws Error when it cannot be.
  std::shared_ptr<const VectorField> wait(std::size_t i) const;
  // Streamed frames only: null otherwise.
  const std::shared_ptr<FieldSteps>& steps() const { return steps_; }

  // Asks a streamed timeline for the frames playback needs from `at` on,
  // going forwards or (with a negative speed) backwards: the pair in use,
  // then the frames after it, wrapping with `loop`, as many as the steps keep.
  void readAhead(const Position& at, bool backwards, bool loop) const;
  // The frame after the pair `at` of `n` in the direction of play, if there
  // is one other than the pair (what walls may upload ahead of need).
  static std::optional<std::size_t> upcomingIndex(std::size_t n, const Position& at, bool backwards,
                                                  bool loop);
  // The frames readAhead asks for, of `n`, at most `count`.
  static std::vector<std::size_t> aheadOrder(std::size_t n, std::size_t count, const Position& at,
                                             bool backwards, bool loop);

 private:
  std::vector<double> times_;
  std::vector<std::shared_ptr<const VectorField>> frames_;  // held frames (empty when streamed)
  std::shared_ptr<FieldSteps> steps_;
};

}  // namespace sandstorm
