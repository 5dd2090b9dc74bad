#include "contexts/bench/gpu_stopwatch.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace sandstorm::bench {

void GpuStopwatch::begin() {
  if (used_ == queries_.size()) queries_.push_back(gl::createQuery(GL_TIME_ELAPSED));
  glBeginQuery(GL_TIME_ELAPSED, queries_[used_].id());
}

void GpuStopwatch::end() {
  glEndQuery(GL_TIME_ELAPSED);
  ++used_;
}

std::vector<double> GpuStopwatch::intervalsMs() {
  std::vector<double> ms(used_);
  for (std::size_t i = 0; i < used_; ++i) {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(queries_[i].id(), GL_QUERY_RESULT, &ns);
    ms[i] = double(ns) * 1e-6;
  }
  return ms;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(mid), values.end());
  double m = values[mid];
  if (values.size() % 2 == 0) {
    const double below = *std::max_element(values.begin(), values.begin() + std::ptrdiff_t(mid));
    m = 0.5 * (m + below);
  }
  return m;
}

}  // namespace sandstorm::bench
