// TimestampSpans: the GPU time of stretches of commands, each with a tag,
// from pairs of GL_TIMESTAMP queries (which, unlike GL_TIME_ELAPSED, may sit
// inside another timer's query), read back only once the GPU has written
// them: poll() never waits. Queries are reused once read.
//   spans.begin(tag); ...commands...; spans.end();
//   for (auto [tag, ms] : spans.poll()) ...
#pragma once

#include <deque>
#include <utility>
#include <vector>

#include "contexts/gl/objects.h"

namespace sandstorm::gl {

class TimestampSpans {
 public:
  void begin(int tag);
  void end();
  // The spans the GPU has finished since the last call, oldest first: (tag, ms).
  std::vector<std::pair<int, double>> poll();

 private:
  struct Span {
    Query start, stop;
    int tag = 0;
  };
  std::deque<Span> pending_;
  std::vector<Span> spare_;
  bool open_ = false;
};

}  // namespace sandstorm::gl
