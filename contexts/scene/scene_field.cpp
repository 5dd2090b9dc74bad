#include "contexts/scene/scene_field.h"

#include <epoxy/gl.h>

#include "contexts/particles/sim_block.h"

namespace sandstorm {

SceneField::SceneField() : block_(gl::createBuffer()) {
  glNamedBufferStorage(block_.id(), sizeof(SimBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void SceneField::set(const ParticleState& state, const FieldUpdate& field, float blend, float dt,
                     const HeightMap* ground) {
  environment_.setField(field.field, field.placement, field.next);
  environment_.setSparse(field.sparse);
  sparse_ = field.field && field.sparse;
  SimBlockInputs inputs;
  environment_.describe(inputs);
  inputs.state = &state;
  inputs.step.fieldBlend = field.next ? blend : 0.0f;
  inputs.step.dt = dt;
  inputs.obstacleGround = ground;
  obstacles_ = collisionShapes(state, inputs.terrain ? inputs.terrain : ground);
  SimBlock block;
  fillSimBlock(inputs, block);
  glNamedBufferSubData(block_.id(), 0, sizeof(block), &block);
  has_ = field.field != nullptr;
  if (field.colorGrid) colorGrid_.show(field.colorGrid);
  if (field.nextColorGrid) nextColorGrid_.show(field.nextColorGrid);
}

void SceneField::bindColorGrid() const {
  if (colorGrid_.holds()) colorGrid_.bindTexture(5);
  if (nextColorGrid_.holds()) nextColorGrid_.bindTexture(6);
}

SceneField::Binding::Binding(const SceneField& field, const ParticleState& state) {
  GLint previous = 0;
  glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 0, &previous);
  previous_ = previous;
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, field.block_.id());
  field.environment_.bind(state);
}

SceneField::Binding::~Binding() {
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, GLuint(previous_));
}

}  // namespace sandstorm
