#include "contexts/scene/slice_renderer.h"

#include <epoxy/gl.h>

#include "core/flow/slice_polygon.h"

namespace sandstorm {

SliceRenderer::SliceRenderer(SceneField& field)
    : field_(field),
      program_(std::vector<std::string>{"slice.vert", "slice.frag"}),
      emptyVao_(gl::createVertexArray()) {}

void SliceRenderer::update(const ParticleState& state, const FieldUpdate* field) {
  polygon_.clear();
  if (!state.slice.enabled || !field || !field->field) return;
  state_ = state;
  polygon_ = slicePolygon(field->field->bounds(), field->placement, state.slice.origin,
                          state.slice.normal);
}

void SliceRenderer::draw() const {
  if (polygon_.size() < 3 || !field_.has()) return;
  const SceneField::Binding binding(field_, state_);
  program_.use();
  glm::vec4 corners[6]{};
  for (std::size_t i = 0; i < polygon_.size() && i < 6; ++i)
    corners[i] = glm::vec4(polygon_[i], 1.0f);
  glProgramUniform4fv(program_.id(), 0, 6, &corners[0].x);
  const float opacity = state_.slice.opacity;
  glProgramUniform1f(program_.id(), 6, opacity);
  const bool blend = opacity < 1.0f;
  if (blend) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
  }
  glDisable(GL_CULL_FACE);
  glBindVertexArray(emptyVao_.id());
  glDrawArrays(GL_TRIANGLE_FAN, 0, GLsizei(std::min<std::size_t>(polygon_.size(), 6)));
  glBindVertexArray(0);
  if (blend) {
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
  }
}

}  // namespace sandstorm
