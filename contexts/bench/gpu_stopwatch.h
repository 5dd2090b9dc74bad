// GpuStopwatch: GPU time of repeated stretches of commands (GL_TIME_ELAPSED
// queries), kept until the caller asks for them. For the benchmark: reading the
// results waits for the GPU, so read after the timed frames, never inside.
// One stopwatch runs at a time (GL allows one time-elapsed query at once).
#pragma once

#include <cstddef>
#include <vector>

#include "contexts/gl/objects.h"

namespace sandstorm::bench {

class GpuStopwatch {
 public:
  void begin();
  void end();
  // Every interval since the last clear(), in milliseconds. Waits for the GPU.
  std::vector<double> intervalsMs();
  void clear() { used_ = 0; }

 private:
  std::vector<gl::Query> queries_;
  std::size_t used_ = 0;
};

// The median of `values` (0 for none).
double median(std::vector<double> values);

}  // namespace sandstorm::bench
