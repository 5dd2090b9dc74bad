#include "core/io/field_sequence.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>

#include "core/io/field_format.h"
#include "core/io/field_loader.h"
#include "core/io/pvd_file.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

std::string frameName(const std::string& pattern, int index) {
  char buffer[4096];
  const int n = std::snprintf(buffer, sizeof(buffer), pattern.c_str(), index);
  if (n < 0 || std::size_t(n) >= sizeof(buffer))
    throw Error(concat("file pattern '", pattern, "' is too long"));
  return buffer;
}

void checkPattern(const std::string& pattern) {
  // Exactly one %[0][width]d, and %% for a literal percent sign.
  static const std::regex conversion("%(%|0?[0-9]*d)");
  int count = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') continue;
    std::smatch m;
    const std::string rest = pattern.substr(i);
    if (!std::regex_search(rest, m, conversion, std::regex_constants::match_continuous))
      throw Error(concat("file pattern '", pattern, "': '%' at ", i,
                         " is not %d, %0Nd or %%; expected one integer conversion"));
    if (m.str(1) != "%") ++count;
    i += m.length(0) - 1;
  }
  if (count != 1)
    throw Error(concat("file pattern '", pattern, "' has ", count,
                       " integer conversions; expected exactly one, e.g. step_%03d.vti"));
}

}  // namespace

FieldSequence::FieldSequence(std::vector<double> times, std::vector<VectorField> frames,
                             Playback playback)
    : times_(std::move(times)), frames_(std::move(frames)), playback_(playback) {
  if (frames_.empty()) throw Error("FieldSequence: no frames");
  if (times_.size() != frames_.size())
    throw Error(concat("FieldSequence: ", times_.size(), " times for ", frames_.size(), " frames"));
  for (std::size_t i = 0; i < times_.size(); ++i) {
    if (!std::isfinite(times_[i]))
      throw Error(concat("FieldSequence: time of frame ", i, " is not finite"));
    if (i > 0 && !(times_[i] > times_[i - 1]))
      throw Error(concat("FieldSequence: frame ", i, " at t = ", times_[i],
                         " does not come after frame ", i - 1, " at t = ", times_[i - 1]));
    const VectorField& f = frames_[i];
    const VectorField& first = frames_.front();
    if (f.dims() != first.dims() || f.bounds().min != first.bounds().min ||
        f.bounds().max != first.bounds().max)
      throw Error(concat("FieldSequence: frame ", i, " has dims ", f.dims().x, "x", f.dims().y, "x",
                         f.dims().z, " and bounds differing from frame 0's ", first.dims().x, "x",
                         first.dims().y, "x", first.dims().z,
                         "; expected every frame on the same grid"));
  }
}

FieldSequence FieldSequence::fromPvd(const std::filesystem::path& pvd, const LoadOptions& options,
                                     Playback playback) {
  const std::vector<PvdFrame> list = readPvd(pvd);
  std::vector<double> times;
  std::vector<VectorField> frames;
  double bytes = 0.0;
  for (const PvdFrame& f : list) {
    frames.push_back(loadFieldParts(f.parts, pvd, options));
    times.push_back(f.time);
    bytes += 12.0 * double(frames.back().pointCount());
    if (bytes > double(options.memoryBudget))
      throw Error(concat(pvd.string(),
                         ": its frames together exceed the memory budget (field.memory_budget) of ",
                         options.memoryBudget, " bytes at ", f.file().string(),
                         "; lower the resolution (field.resolution)"));
    if (frames.size() > 1 && (frames.back().dims() != frames.front().dims() ||
                              frames.back().bounds().min != frames.front().bounds().min ||
                              frames.back().bounds().max != frames.front().bounds().max))
      throw Error(concat(pvd.string(), ": frame ", f.file().string(),
                         " has other dims or bounds than ", list.front().file().string(),
                         "; expected every frame on the same grid"));
  }
  return FieldSequence(std::move(times), std::move(frames), playback);
}

FieldSequence FieldSequence::fromFile(const std::filesystem::path& path, const LoadOptions& options,
                                      Playback playback, LoadReport* report) {
  if (detectFieldFormat(path) == FieldFormat::VtkCollection) {
    if (report) *report = LoadReport{};
    FieldSequence sequence = fromPvd(path, options, playback);
    if (report) {
      loadFieldParts(readPvd(path).front().parts, path, options, report);
      for (std::size_t i = 0; i < sequence.size(); ++i)
        report->times.push_back(sequence.time(i));
    }
    return sequence;
  }
  LoadReport local;
  LoadReport& first = report ? *report : local;
  std::vector<VectorField> frames;
  frames.push_back(loadField(path, options, &first));
  if (first.times.size() <= 1)
    return FieldSequence({first.times.empty() ? 0.0 : first.times.front()}, std::move(frames),
                         playback);
  // Every step on the grid the first one chose.
  LoadOptions step = options;
  step.resolution = frames.front().dims();
  double bytes = 12.0 * double(frames.front().pointCount());
  for (std::size_t i = 1; i < first.times.size(); ++i) {
    step.timeStep = i;
    LoadReport r;
    frames.push_back(loadField(path, step, &r));
    bytes += 12.0 * double(frames.back().pointCount());
    if (bytes > double(options.memoryBudget))
      throw Error(concat(path.string(), ": its ", first.times.size(),
                         " time steps together exceed the memory budget (field.memory_budget) of ",
                         options.memoryBudget, " bytes at step ", i, " (t = ", first.times[i],
                         "); lower the resolution (field.resolution)"));
    if (frames.back().bounds().min != frames.front().bounds().min ||
        frames.back().bounds().max != frames.front().bounds().max)
      throw Error(concat(path.string(), ": time step ", i, " (t = ", first.times[i],
                         ") covers other bounds than the first; expected every step on the "
                         "same grid (a moving mesh is not supported)"));
  }
  return FieldSequence(first.times, std::move(frames), playback);
}

FieldSequence FieldSequence::fromPattern(const std::string& pattern, double startTime, double dt,
                                         const LoadOptions& options, int firstIndex,
                                         Playback playback) {
  checkPattern(pattern);
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw Error(concat("file pattern '", pattern, "': time step ", dt, "; expected dt > 0"));
  std::vector<double> times;
  std::vector<VectorField> frames;
  double bytes = 0.0;
  for (int index = firstIndex;; ++index) {
    const std::string name = frameName(pattern, index);
    if (!std::filesystem::exists(name)) break;
    frames.push_back(loadField(name, options));
    times.push_back(startTime + dt * double(index - firstIndex));
    bytes += 12.0 * double(frames.back().pointCount());
    if (bytes > double(options.memoryBudget))
      throw Error(concat(name, ": the frames of '", pattern,
                         "' together exceed the memory budget (field.memory_budget) of ",
                         options.memoryBudget, " bytes; lower the resolution (field.resolution)"));
    if (frames.size() > 1 && (frames.back().dims() != frames.front().dims() ||
                              frames.back().bounds().min != frames.front().bounds().min ||
                              frames.back().bounds().max != frames.front().bounds().max))
      throw Error(concat(name, ": other dims or bounds than ", frameName(pattern, firstIndex),
                         "; expected every frame of '", pattern, "' on the same grid"));
  }
  if (frames.empty())
    throw Error(concat("file pattern '", pattern, "': no file ", frameName(pattern, firstIndex)));
  return FieldSequence(std::move(times), std::move(frames), playback);
}

FrameBlend FieldSequence::blendAt(double t) const {
  const std::size_t n = times_.size();
  if (n == 1 || std::isnan(t)) return {0, 0, 0.0f};
  const double start = times_.front(), end = times_.back();
  if (playback_ == Playback::Loop) {
    const double period = end - start;
    t = start + (t - start - period * std::floor((t - start) / period));
  }
  if (t <= start) return {0, 0, 0.0f};
  if (t >= end) return {n - 1, n - 1, 0.0f};
  const auto upper = std::upper_bound(times_.begin(), times_.end(), t);
  const std::size_t b = std::size_t(upper - times_.begin());
  const std::size_t a = b - 1;
  const double w = (t - times_[a]) / (times_[b] - times_[a]);
  return {a, b, float(std::clamp(w, 0.0, 1.0))};
}

VectorField FieldSequence::at(double t) const {
  const FrameBlend blend = blendAt(t);
  if (blend.weight == 0.0f) return frames_[blend.first];
  const auto a = frames_[blend.first].values();
  const auto b = frames_[blend.second].values();
  std::vector<glm::vec3> out(a.size());
  const float w = blend.weight;
  for (std::size_t i = 0; i < a.size(); ++i)
    out[i] = a[i] + (b[i] - a[i]) * w;
  return VectorField(bounds(), dims(), std::move(out));
}

glm::vec3 FieldSequence::sample(const glm::vec3& p, double t) const {
  const FrameBlend blend = blendAt(t);
  const glm::vec3 a = frames_[blend.first].sample(p);
  if (blend.weight == 0.0f) return a;
  const glm::vec3 b = frames_[blend.second].sample(p);
  return a + (b - a) * blend.weight;
}

}  // namespace sandstorm
