// GpuTimer: GPU time of a stretch of commands (GL_TIME_ELAPSED queries), read
// back a few frames later so measuring never stalls the pipeline.
#pragma once

#include <array>

#include "contexts/gl/objects.h"

namespace sandstorm::gl {

class GpuTimer {
 public:
  void begin();
  void end();
  // The most recent measurement that is ready, in milliseconds (0 before the first).
  double lastMs();

 private:
  static constexpr int kRing = 4;
  std::array<Query, kRing> queries_;
  std::array<bool, kRing> pending_{};
  int next_ = 0;
  double lastMs_ = 0.0;
};

}  // namespace sandstorm::gl
