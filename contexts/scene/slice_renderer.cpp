#include "contexts/scene/slice_renderer.h"

#include <epoxy/gl.h>

#include "core/flow/slice_arrows.h"
#include "core/flow/slice_polygon.h"

namespace sandstorm {

SliceRenderer::SliceRenderer(SceneField& field)
    : field_(field),
      program_({"slice.vert", "slice.frag"}, {"OBSTACLES"}),
      arrowProgram_(std::vector<std::string>{"slice_arrows.vert", "slice_arrows.frag"}),
      emptyVao_(gl::createVertexArray()),
      arrowVao_(gl::createVertexArray()) {}

void SliceRenderer::update(const ParticleState& state,
                           const std::shared_ptr<const FieldUpdate>& field, float blend) {
  polygon_.clear();
  if (!state.slice.enabled || !field || !field->field) {
    arrowPoints_ = 0;
    arrowsOf_ = {};
    return;
  }
  state_ = state;
  polygon_ = slicePolygon(field->field->bounds(), field->placement, state.slice.origin,
                          state.slice.normal);
  // The arrows are made again only when what they show changed.
  const ArrowsOf now{field,
                     blend,
                     state.slice.origin,
                     state.slice.normal,
                     state.slice.arrows,
                     state.sim.fieldStrength,
                     field_.obstacles()};
  if (now == arrowsOf_) return;
  arrowsOf_ = now;
  arrowPoints_ = 0;
  if (state.slice.arrows <= 0) return;
  PhysicsInputs in;
  in.field = field->field.get();
  in.nextField = field->next.get();
  in.sparse = field->sparse.get();
  in.blend = blend;
  in.placement = field->placement;
  in.settings = state.sim;
  in.obstacles = field_.obstacles();
  const std::vector<glm::vec3> lines = arrowLines(
      sliceArrows(polygon_, state.slice.normal, state.slice.arrows, in), state.slice.normal);
  if (lines.empty()) return;
  if (lines.size() > arrowCapacity_) {
    arrowCapacity_ = lines.size();
    arrowLines_ = gl::createBuffer();
    glNamedBufferStorage(arrowLines_.id(), GLsizeiptr(arrowCapacity_ * sizeof(glm::vec3)), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    glVertexArrayVertexBuffer(arrowVao_.id(), 0, arrowLines_.id(), 0, sizeof(glm::vec3));
    glEnableVertexArrayAttrib(arrowVao_.id(), 0);
    glVertexArrayAttribFormat(arrowVao_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(arrowVao_.id(), 0, 0);
  }
  glNamedBufferSubData(arrowLines_.id(), 0, GLsizeiptr(lines.size() * sizeof(glm::vec3)),
                       lines.data());
  arrowPoints_ = int(lines.size());
}

void SliceRenderer::draw() const {
  if (!visible()) return;
  const SceneField::Binding binding(field_, state_);
  const gl::Program& program = program_.get(field_);
  program.use();
  glm::vec4 corners[6]{};
  for (std::size_t i = 0; i < polygon_.size() && i < 6; ++i)
    corners[i] = glm::vec4(polygon_[i], 1.0f);
  glProgramUniform4fv(program.id(), 0, 6, &corners[0].x);
  const float opacity = state_.slice.opacity;
  glProgramUniform1f(program.id(), 6, opacity);
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
  if (arrowPoints_ > 0) {
    // Drawn over the slice they lie in: a small depth offset toward the eye.
    arrowProgram_.use();
    glBindVertexArray(arrowVao_.id());
    glDrawArrays(GL_LINES, 0, arrowPoints_);
    glBindVertexArray(0);
  }
}

}  // namespace sandstorm
