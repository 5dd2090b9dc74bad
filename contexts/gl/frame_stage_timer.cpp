#include "contexts/gl/frame_stage_timer.h"

#include <epoxy/gl.h>

namespace sandstorm::gl {

void FrameStageTimer::begin(Stage stage) {
  Frame& f = frames_[std::size_t(current_)];
  if (f.used == kPerFrame) return;  // more measurements than a frame has room for: not timed
  Query& start = f.starts[std::size_t(f.used)];
  if (!start) start = createQuery(GL_TIMESTAMP);
  f.stages[std::size_t(f.used)] = stage;
  glQueryCounter(start.id(), GL_TIMESTAMP);
  open_ = true;
}

void FrameStageTimer::end() {
  if (!open_) return;
  Frame& f = frames_[std::size_t(current_)];
  Query& stop = f.ends[std::size_t(f.used)];
  if (!stop) stop = createQuery(GL_TIMESTAMP);
  glQueryCounter(stop.id(), GL_TIMESTAMP);
  open_ = false;
  ++frames_[std::size_t(current_)].used;
}

void FrameStageTimer::endFrame() {
  frames_[std::size_t(current_)].closed = true;
  harvest();
  current_ = (current_ + 1) % kFrames;
  Frame& next = frames_[std::size_t(current_)];
  // Still not in after kFrames frames (a GPU far behind): that measurement is dropped.
  next.used = 0;
  next.closed = false;
}

void FrameStageTimer::harvest() {
  // Oldest first, so latest_ ends at the newest frame that is complete.
  for (int k = 1; k <= kFrames; ++k) {
    Frame& f = frames_[std::size_t((current_ + k) % kFrames)];
    if (!f.closed || f.used == 0) continue;
    bool ready = true;
    for (int i = 0; i < f.used && ready; ++i) {
      GLint available = 0;
      glGetQueryObjectiv(f.ends[std::size_t(i)].id(), GL_QUERY_RESULT_AVAILABLE, &available);
      ready = available != 0;
    }
    if (!ready) continue;
    Times t{};
    for (int i = 0; i < f.used; ++i) {
      GLuint64 from = 0, to = 0;
      glGetQueryObjectui64v(f.starts[std::size_t(i)].id(), GL_QUERY_RESULT, &from);
      glGetQueryObjectui64v(f.ends[std::size_t(i)].id(), GL_QUERY_RESULT, &to);
      t[std::size_t(f.stages[std::size_t(i)])] += to > from ? double(to - from) * 1e-6 : 0.0;
    }
    latest_ = t;
    f.closed = false;
    f.used = 0;
  }
}

}  // namespace sandstorm::gl
