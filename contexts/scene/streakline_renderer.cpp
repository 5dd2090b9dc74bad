#include "contexts/scene/streakline_renderer.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace sandstorm {

StreaklineRenderer::StreaklineRenderer(SceneField& field)
    : field_(field),
      update_({"streak_update.comp"}, {"OBSTACLES"}),
      draw_(std::vector<std::string>{"streakline.vert", "streakline.frag"}),
      emptyVao_(gl::createVertexArray()) {}

void StreaklineRenderer::update(const ParticleState& state, float dt, bool reset) {
  enabled_ = state.render.streaklines && field_.has();
  if (!enabled_) {
    length_ = 0;  // on again: start afresh
    return;
  }
  const int length = std::clamp(state.render.streakLength, 2, 1024);
  if (length != length_ || reset) {
    length_ = length;
    head_ = length - 1;
    ring_ = gl::createBuffer();
    const std::vector<glm::vec4> empty(std::size_t(ParticleState::kMaxEmitters * length * 2),
                                       glm::vec4(0.0f));
    glNamedBufferStorage(ring_.id(), GLsizeiptr(empty.size() * sizeof(glm::vec4)), empty.data(), 0);
  }
  if (!(dt > 0.0f)) return;
  head_ = (head_ + 1) % length_;
  std::uint32_t releasing = 0;
  for (std::size_t e = 0; e < state.emitters.size() && e < 32; ++e)
    if (streaks(state.emitters[e])) releasing |= 1u << e;
  const SceneField::Binding binding(field_, state);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 11, ring_.id());
  const gl::Program& update = update_.get(field_);
  update.use();
  glProgramUniform1i(update.id(), 0, length_);
  glProgramUniform1i(update.id(), 1, head_);
  glProgramUniform1ui(update.id(), 2, releasing);
  glDispatchCompute(GLuint((ParticleState::kMaxEmitters * length_ + 63) / 64), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void StreaklineRenderer::draw() const {
  if (!visible()) return;
  draw_.use();
  glProgramUniform1i(draw_.id(), 0, length_);
  glProgramUniform1i(draw_.id(), 1, head_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 11, ring_.id());
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glBindVertexArray(emptyVao_.id());
  glDrawArrays(GL_LINES, 0, GLsizei(ParticleState::kMaxEmitters * (length_ - 1) * 2));
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

std::vector<StreakPoint> StreaklineRenderer::readBack(int emitter) const {
  std::vector<StreakPoint> out;
  if (length_ == 0) return out;
  std::vector<glm::vec4> ring(std::size_t(ParticleState::kMaxEmitters * length_ * 2));
  glGetNamedBufferSubData(ring_.id(), 0, GLsizeiptr(ring.size() * sizeof(glm::vec4)), ring.data());
  for (int j = 0; j < length_; ++j) {
    const std::size_t at = std::size_t(emitter * length_ + (head_ - j + length_) % length_) * 2;
    if (ring[at].w > 0.5f) out.push_back({glm::vec3(ring[at]), glm::vec3(ring[at + 1]), true});
  }
  return out;
}

}  // namespace sandstorm
