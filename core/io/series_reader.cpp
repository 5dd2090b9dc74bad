#include "core/io/series_reader.h"

#include <algorithm>
#include <chrono>

#include "core/field/grid_match.h"
#include "core/io/field_loader.h"
#include "core/io/grid_resample.h"
#include "core/util/error.h"
#include "core/util/log.h"
#include "core/util/parallel_for.h"

namespace sandstorm {
namespace {

bool contains(const std::vector<std::size_t>& v, std::size_t i) {
  return std::find(v.begin(), v.end(), i) != v.end();
}

// A step of several parts is the same step where every part is: their sizes
// summed, the newest modification, present where all are.
FileIdentity identityOf(const SeriesReader::Source& s) {
  if (s.parts.size() <= 1) return FileIdentity::of(s.file);
  FileIdentity out{.present = true};
  for (const std::filesystem::path& part : s.parts) {
    const FileIdentity one = FileIdentity::of(part);
    out.present = out.present && one.present;
    out.size += one.size;
    out.modified = std::max(out.modified, one.modified);
  }
  return out;
}

// A step on another grid than the first's, resampled onto it; what was
// done, for the log.
std::shared_ptr<const VectorField> ontoFirstGrid(std::shared_ptr<const VectorField> field,
                                                 const VectorField* grid, const std::string& name,
                                                 std::string* note) {
  if (!grid) return field;
  const std::string difference = gridDifference(*field, *grid);
  if (difference.empty()) return field;
  auto onto = std::make_shared<const VectorField>(resampleOnto(*field, *grid));
  const std::size_t outside = onto->invalidCount();
  if (note)
    *note = concat(name, ": ", difference, "; resampled onto the first step's grid",
                   outside > 0 ? concat(", ", outside, " of its ", onto->pointCount(),
                                        " points outside this step (marked outside the field)")
                               : std::string());
  return onto;
}

}  // namespace

SeriesReader::SeriesReader(std::vector<Source> sources, LoadOptions options,
                           std::shared_ptr<const VectorField> first, std::size_t capacity,
                           int threads)
    : sources_(std::move(sources)),
      options_(std::move(options)),
      first_(std::move(first)),
      capacity_(std::max<std::size_t>(capacity, 2)) {
  if (sources_.empty() || !first_) throw Error("field series: no first step to start from");
  held_[0] = first_;
  for (const Source& s : sources_)
    identities_.push_back(identityOf(s));
  const unsigned readers = unsigned(std::max(threads, 1));
  const unsigned share = std::max(1u, std::thread::hardware_concurrency() / readers);
  for (unsigned t = 0; t < readers; ++t)
    threads_.emplace_back([this, share] { run(share); });
}

SeriesReader::~SeriesReader() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  for (std::thread& t : threads_)
    t.join();
}

std::shared_ptr<const VectorField> SeriesReader::read(const Source& source,
                                                      const LoadOptions& options,
                                                      const VectorField* grid, std::string* note) {
  LoadOptions step = options;
  step.timeStep = source.timeStep;
  step.showProgress = false;  // read in the background, as playback needs it
  auto field = std::make_shared<const VectorField>(
      source.parts.size() > 1 ? loadFieldParts(source.parts, source.file, step)
                              : loadField(source.file, step));
  const std::string name =
      concat(source.file.string(),
             source.timeStep > 0 ? concat(" (time step ", source.timeStep, ")") : "");
  return ontoFirstGrid(std::move(field), grid, name, note);
}

void SeriesReader::noteResampled(const std::string& note) {
  if (note.empty()) return;
  // Once at info (a moving mesh resamples every step: the rest at debug).
  if (!saidResampled_.exchange(true))
    log::info("field series: ", note, " (later steps on other grids are resampled alike)");
  else
    log::debug("field series: ", note);
}

void SeriesReader::want(const std::vector<std::size_t>& order) {
  {
    std::lock_guard lock(mutex_);
    std::vector<std::size_t> wanted;
    for (std::size_t i : order)
      if (i < sources_.size() && !contains(wanted, i) && wanted.size() < capacity_)
        wanted.push_back(i);
    // Asked every frame; the steps change only as playback moves on.
    if (wanted == wanted_) return;
    wanted_ = std::move(wanted);
    // Drop what playback has left behind (a wall showing it keeps its own reference).
    for (auto it = held_.begin(); it != held_.end();)
      it = contains(wanted_, it->first) ? std::next(it) : held_.erase(it);
  }
  changed_.notify_all();
}

FileIdentity SeriesReader::identity(std::size_t i) const {
  std::lock_guard lock(mutex_);
  return i < identities_.size() ? identities_[i] : FileIdentity{};
}

std::shared_ptr<const VectorField> SeriesReader::get(std::size_t i) {
  std::lock_guard lock(mutex_);
  const auto it = held_.find(i);
  return it == held_.end() ? nullptr : it->second;
}

std::size_t SeriesReader::size() const {
  std::lock_guard lock(mutex_);
  return sources_.size();
}

void SeriesReader::append(const std::filesystem::path& file,
                          std::shared_ptr<const VectorField> frame) {
  if (!frame) throw Error("field series: a missing step");
  std::string note;
  frame = ontoFirstGrid(std::move(frame), first_.get(), file.string(), &note);
  noteResampled(note);
  const FileIdentity identity = FileIdentity::of(file);
  {
    std::lock_guard lock(mutex_);
    const std::size_t step = sources_.size();
    sources_.push_back({file, 0});
    identities_.push_back(identity);
    held_[step] = std::move(frame);
    // Held until playback says what it wants; beyond capacity, the steps it
    // does not want go first, the oldest first, so memory stays flat.
    for (auto it = held_.begin(); held_.size() > capacity_ && it != held_.end();)
      it = it->first != step && !contains(wanted_, it->first) ? held_.erase(it) : std::next(it);
  }
  changed_.notify_all();
}

void SeriesReader::appendFile(const std::filesystem::path& file) {
  const FileIdentity identity = FileIdentity::of(file);
  std::lock_guard lock(mutex_);
  sources_.push_back({file, 0});
  identities_.push_back(identity);
}

std::shared_ptr<const VectorField> SeriesReader::wait(std::size_t i) {
  std::unique_lock lock(mutex_);
  if (i >= sources_.size())
    throw Error(concat("field series: step ", i, " asked of ", sources_.size()));
  if (!contains(wanted_, i)) {
    // Asked for out of order (a replay, the start): first in line.
    wanted_.insert(wanted_.begin(), i);
    if (wanted_.size() > capacity_) wanted_.pop_back();
    changed_.notify_all();
  }
  changed_.wait(lock, [&] { return held_.count(i) || failed_.count(i) || stop_; });
  if (const auto f = failed_.find(i); f != failed_.end()) throw Error(f->second);
  if (stop_) throw Error("field series: reading stopped (the run ends)");
  return held_.at(i);
}

std::string SeriesReader::failure(std::size_t i) const {
  std::lock_guard lock(mutex_);
  const auto it = failed_.find(i);
  return it == failed_.end() ? std::string() : it->second;
}

std::string SeriesReader::name(std::size_t i) const {
  std::lock_guard lock(mutex_);
  if (i >= sources_.size()) return {};
  const Source& s = sources_[i];
  // Steps of one file (Exodus, EnSight, ...) are told apart by their index.
  const bool oneFile = sources_.size() > 1 && sources_[0].file == sources_[1].file;
  if (oneFile) return concat(s.file.string(), " (time step ", s.timeStep, ")");
  if (s.parts.size() > 1)
    return concat(s.file.string(), " and ", s.parts.size() - 1, " more part(s)");
  return s.file.string();
}

std::vector<std::size_t> SeriesReader::resident() const {
  std::lock_guard lock(mutex_);
  std::vector<std::size_t> out;
  for (const auto& [i, field] : held_)
    out.push_back(i);
  return out;
}

SeriesReader::Stats SeriesReader::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

bool SeriesReader::nextToRead(std::size_t& step) const {
  for (std::size_t i : wanted_)
    if (!held_.count(i) && !failed_.count(i) && !contains(reading_, i)) {
      step = i;
      return true;
    }
  return false;
}

void SeriesReader::run(unsigned cores) {
  // Each reader reads a step of its own: its passes over the step (the
  // check of each vector, rounding to halves) share the cores with the others.
  const ChunkThreadLimit limit(cores);
  std::unique_lock lock(mutex_);
  for (;;) {
    std::size_t step = 0;
    changed_.wait(lock, [&] { return stop_ || nextToRead(step); });
    if (stop_) return;
    reading_.push_back(step);
    const Source source = sources_[step];
    lock.unlock();
    const auto start = std::chrono::steady_clock::now();
    std::shared_ptr<const VectorField> field;
    std::string error, note;
    try {
      field = read(source, options_, first_.get(), &note);
      noteResampled(note);
    } catch (const Error& e) {
      error = e.what();
    } catch (const std::bad_alloc&) {
      error = concat(name(step),
                     ": out of memory reading it (lower field.read_ahead or "
                     "field.resolution)");
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    lock.lock();
    reading_.erase(std::find(reading_.begin(), reading_.end(), step));
    if (!error.empty()) {
      failed_[step] = error;
    } else {
      stats_.stepsRead += 1;
      stats_.bytesRead += 12.0 * double(field->pointCount());
      stats_.secondsReading += seconds;
      // Kept only while still wanted (playback may have moved on meanwhile).
      if (contains(wanted_, step)) held_[step] = std::move(field);
    }
    changed_.notify_all();
  }
}

}  // namespace sandstorm
