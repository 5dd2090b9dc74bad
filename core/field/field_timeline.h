// FieldTimeline: a time-varying field as the main context plays it: frames
// (shared, never copied per wall) at increasing times, and for any playback
// time the two frames around it and the weight between them. The walls blend
// the two frames themselves (field + (next - field) * weight), so a frame
// travels to them once, when it comes into use, and only the weight travels
// every frame.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "core/field/vector_field.h"

namespace sandstorm {

class FieldTimeline {
 public:
  struct Position {
    std::size_t first = 0, second = 0;
    float weight = 0.0f;  // towards `second`
  };

  // Throws Error unless there are frames, times increase, and every frame
  // shares the first one's dims and bounds.
  FieldTimeline(std::vector<double> times, std::vector<std::shared_ptr<const VectorField>> frames);

  // Before the start: the first frame; past the end: the last, or with `loop`
  // wrapped into [start, end) (the last frame blends back into the first).
  Position at(double time, bool loop) const;

  // A new last frame (a simulation's next step, FieldStream): throws Error,
  // changing nothing, unless it follows the last frame's time and shares its grid.
  void append(double time, std::shared_ptr<const VectorField> frame);

  std::size_t size() const { return frames_.size(); }
  const std::shared_ptr<const VectorField>& frame(std::size_t i) const { return frames_[i]; }
  double time(std::size_t i) const { return times_[i]; }

 private:
  std::vector<double> times_;
  std::vector<std::shared_ptr<const VectorField>> frames_;
};

}  // namespace sandstorm
