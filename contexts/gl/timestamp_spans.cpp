#include "contexts/gl/timestamp_spans.h"

#include <epoxy/gl.h>

namespace sandstorm::gl {

void TimestampSpans::begin(int tag) {
  if (open_) return;
  Span span;
  if (!spare_.empty()) {
    span = std::move(spare_.back());
    spare_.pop_back();
  } else {
    span.start = createQuery(GL_TIMESTAMP);
    span.stop = createQuery(GL_TIMESTAMP);
  }
  span.tag = tag;
  glQueryCounter(span.start.id(), GL_TIMESTAMP);
  pending_.push_back(std::move(span));
  open_ = true;
}

void TimestampSpans::end() {
  if (!open_) return;
  glQueryCounter(pending_.back().stop.id(), GL_TIMESTAMP);
  open_ = false;
}

std::vector<std::pair<int, double>> TimestampSpans::poll() {
  std::vector<std::pair<int, double>> done;
  // In order: a later span is never ready before an earlier one's stop.
  while (!pending_.empty() && !(open_ && pending_.size() == 1)) {
    Span& s = pending_.front();
    GLint ready = 0;
    glGetQueryObjectiv(s.stop.id(), GL_QUERY_RESULT_AVAILABLE, &ready);
    if (!ready) break;
    GLuint64 start = 0, stop = 0;
    glGetQueryObjectui64v(s.start.id(), GL_QUERY_RESULT, &start);
    glGetQueryObjectui64v(s.stop.id(), GL_QUERY_RESULT, &stop);
    done.emplace_back(s.tag, stop > start ? double(stop - start) * 1e-6 : 0.0);
    spare_.push_back(std::move(s));
    pending_.pop_front();
  }
  return done;
}

}  // namespace sandstorm::gl
