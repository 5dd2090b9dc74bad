// SeriesReader: the steps of a time series read from disk as playback needs
// them (FieldSteps for a streamed FieldTimeline), on threads of its own.
//
// The main context says each frame which steps it wants, most urgent first
// (the pair being blended, then the next ones in the direction of play:
// FieldTimeline::readAhead). Reader threads take the first wanted step not
// yet in memory; a step no longer wanted is dropped (freed once no wall shows
// it), so at most `capacity` steps are in memory however long the series.
//
// A watched folder's series grows (append): a step the simulation wrote is
// held while playback wants it and read again from its file when wanted later.
//
// Every step is held on the first step's grid (dims and bounds: playback
// blends neighbouring steps point by point): one on another grid (a moving
// or growing mesh, another resolution) is resampled onto it
// (resampleOnto), said in the log. A step that does not read (missing,
// truncated, malformed) fails with its file named and is not tried again.
// Counts bytes and time spent reading, for the log's read rate.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "core/field/field_timeline.h"
#include "core/io/load_options.h"

namespace sandstorm {

class SeriesReader final : public FieldSteps {
 public:
  struct Source {
    std::filesystem::path file;
    std::size_t timeStep = 0;  // within a file of several (Exodus, EnSight, ...)
    // A step stored as several files (a .pvd's parts: file and the others),
    // read together (loadFieldParts); empty or one: `file` alone.
    std::vector<std::filesystem::path> parts;
  };
  struct Stats {
    std::uint64_t stepsRead = 0;
    double bytesRead = 0.0;       // the steps' grids, 12 bytes a point
    double secondsReading = 0.0;  // summed over the threads
  };

  // `first`: step 0, already read (it fixes the grid every step must have).
  // `capacity` >= 2 steps in memory; `threads` >= 1 readers.
  SeriesReader(std::vector<Source> sources, LoadOptions options,
               std::shared_ptr<const VectorField> first, std::size_t capacity, int threads);
  ~SeriesReader() override;
  SeriesReader(const SeriesReader&) = delete;
  SeriesReader& operator=(const SeriesReader&) = delete;

  void want(const std::vector<std::size_t>& order) override;
  std::shared_ptr<const VectorField> get(std::size_t i) override;
  std::shared_ptr<const VectorField> wait(std::size_t i) override;
  std::string failure(std::size_t i) const override;
  std::string name(std::size_t i) const override;
  std::size_t capacity() const override { return capacity_; }
  std::vector<std::size_t> resident() const override;
  FileIdentity identity(std::size_t i) const override;
  void append(const std::filesystem::path& file, std::shared_ptr<const VectorField> frame) override;
  void appendFile(const std::filesystem::path& file) override;
  std::size_t size() const override;

  Stats stats() const;

  // Reads one step, resampled onto `grid` where its grid differs (not when
  // null); `note` then says so, naming the file. Throws Error naming the file.
  static std::shared_ptr<const VectorField> read(const Source& source, const LoadOptions& options,
                                                 const VectorField* grid,
                                                 std::string* note = nullptr);

 private:
  // Logs a step's resampling onto the first grid: the first at info, the rest at debug.
  void noteResampled(const std::string& note);
  // A reader thread's loop; `cores`: the threads each of its passes over a step may use.
  void run(unsigned cores);
  // The first wanted step neither in memory, being read nor failed; false if none.
  bool nextToRead(std::size_t& step) const;

  // Guarded by mutex_ (a watched folder's series grows while readers read).
  std::vector<Source> sources_;
  std::vector<FileIdentity> identities_;  // each source's file when the series was opened
  const LoadOptions options_;
  const std::shared_ptr<const VectorField> first_;
  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<std::size_t> wanted_;
  std::map<std::size_t, std::shared_ptr<const VectorField>> held_;
  std::map<std::size_t, std::string> failed_;
  std::vector<std::size_t> reading_;
  Stats stats_;
  bool stop_ = false;
  std::atomic<bool> saidResampled_{false};
  std::vector<std::thread> threads_;
};

}  // namespace sandstorm
