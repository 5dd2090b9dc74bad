#include "contexts/gl/gpu_timer.h"

#include <epoxy/gl.h>

namespace sandstorm::gl {

void GpuTimer::begin() {
  Query& q = queries_[std::size_t(next_)];
  if (!q) q = createQuery(GL_TIME_ELAPSED);
  if (pending_[std::size_t(next_)]) lastMs();  // harvest before reuse
  glBeginQuery(GL_TIME_ELAPSED, q.id());
}

void GpuTimer::end() {
  glEndQuery(GL_TIME_ELAPSED);
  pending_[std::size_t(next_)] = true;
  next_ = (next_ + 1) % kRing;
}

double GpuTimer::lastMs() {
  // Oldest first, so lastMs_ ends at the newest result available.
  for (int k = 0; k < kRing; ++k) {
    const int i = (next_ + k) % kRing;
    if (!pending_[std::size_t(i)]) continue;
    GLint ready = 0;
    glGetQueryObjectiv(queries_[std::size_t(i)].id(), GL_QUERY_RESULT_AVAILABLE, &ready);
    if (!ready) continue;
    GLuint64 ns = 0;
    glGetQueryObjectui64v(queries_[std::size_t(i)].id(), GL_QUERY_RESULT, &ns);
    lastMs_ = double(ns) * 1e-6;
    pending_[std::size_t(i)] = false;
  }
  return lastMs_;
}

}  // namespace sandstorm::gl
