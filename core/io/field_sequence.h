// FieldSequence: a time-varying field, a list of frames (time, VectorField)
// interpolated linearly in time.
//
// Frames come from a .pvd collection (fromPvd), a file's own time steps
// (fromFile: Exodus, EnSight, OpenFOAM, NetCDF, CGNS) or a numbered file pattern
// (fromPattern: "data/series/step_%03d.vti" with frame n at start + n * dt),
// all loaded at once with loadField(). Every frame must share the dims and
// bounds of the first (Error naming the odd file otherwise), times must
// increase strictly, and all frames together must fit options.memoryBudget.
//
// At time t, between frames a (time ta) and b (time tb):
//   value = (1 - w) * frame(a) + w * frame(b),   w = (t - ta) / (tb - ta)
// blendAt(t) returns (a, b, w) without touching the grids: the main context
// sends the two frame indices and the weight in its frame packets and lets
// each context blend; at(t) builds the blended grid on the CPU.
// Playback::Clamp holds the first frame before the start and the last after
// the end; Playback::Loop wraps t into [start, end) (the last frame is
// followed by a jump back to the first). Read-only after construction:
// safe to share between threads.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/field/vector_field.h"
#include "core/io/load_options.h"

namespace sandstorm {

enum class Playback { Clamp, Loop };

struct FrameBlend {
  std::size_t first = 0;
  std::size_t second = 0;
  float weight = 0.0f;  // of `second`, in [0, 1]
};

class FieldSequence {
 public:
  FieldSequence(std::vector<double> times, std::vector<VectorField> frames,
                Playback playback = Playback::Clamp);

  static FieldSequence fromPvd(const std::filesystem::path& pvd, const LoadOptions& options = {},
                               Playback playback = Playback::Clamp);
  // Any field file: a .pvd's frames, the time steps a file holds itself
  // (Exodus, EnSight, OpenFOAM, NetCDF, CGNS: every step on the grid the
  // first chose), or the one field of a file without time steps. `report`
  // gets the first step's LoadReport (its times: every step's).
  static FieldSequence fromFile(const std::filesystem::path& path, const LoadOptions& options = {},
                                Playback playback = Playback::Clamp, LoadReport* report = nullptr);
  // `pattern` holds one printf integer conversion (%d, %03d, ...); frames are
  // read from index `firstIndex` on until a file is missing.
  static FieldSequence fromPattern(const std::string& pattern, double startTime, double dt,
                                   const LoadOptions& options = {}, int firstIndex = 0,
                                   Playback playback = Playback::Clamp);

  std::size_t size() const { return frames_.size(); }
  double time(std::size_t i) const { return times_[i]; }
  const VectorField& frame(std::size_t i) const { return frames_[i]; }
  double startTime() const { return times_.front(); }
  double endTime() const { return times_.back(); }
  const Box& bounds() const { return frames_.front().bounds(); }
  const glm::ivec3& dims() const { return frames_.front().dims(); }

  // The frames, moved out (the sequence is empty after).
  std::vector<VectorField> takeFrames() && { return std::move(frames_); }

  Playback playback() const { return playback_; }
  void setPlayback(Playback playback) { playback_ = playback; }

  FrameBlend blendAt(double t) const;
  VectorField at(double t) const;
  glm::vec3 sample(const glm::vec3& p, double t) const;

 private:
  std::vector<double> times_;
  std::vector<VectorField> frames_;
  Playback playback_;
};

}  // namespace sandstorm
