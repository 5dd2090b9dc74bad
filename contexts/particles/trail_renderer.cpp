#include "contexts/particles/trail_renderer.h"

#include <epoxy/gl.h>

namespace sandstorm {

TrailRenderer::TrailRenderer()
    : program_(std::vector<std::string>{"trail.vert", "trail.frag"}),
      command_(std::vector<std::string>{"trail_command.comp"}),
      emptyVao_(gl::createVertexArray()),
      commandBuffer_(gl::createBuffer()) {
  glNamedBufferStorage(commandBuffer_.id(), 16, nullptr, 0);
}

void TrailRenderer::draw(const ParticleBackend::Records& r, std::size_t capacity) const {
  if (r.trails == 0 || r.trailLength < 2 || capacity == 0) return;
  const GLuint perRecord = GLuint(r.trailLength - 1) * 2;
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, r.countBuffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 9, commandBuffer_.id());
  command_.use();
  glProgramUniform1ui(command_.id(), 0, r.countOffset / 4);
  glProgramUniform1ui(command_.id(), 1, r.countAdd);
  glProgramUniform1ui(command_.id(), 2, perRecord);
  glProgramUniform1ui(command_.id(), 3, GLuint(capacity));
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT);
  program_.use();
  glProgramUniform1i(program_.id(), 0, r.trailLength);
  glProgramUniform1i(program_.id(), 1, r.trailHead);
  glProgramUniform1ui(program_.id(), 2, r.countOffset / 4);
  glProgramUniform1ui(program_.id(), 3, r.countAdd);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, r.positionLife);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, r.velocityKind);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, r.countBuffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, r.trails);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glBindVertexArray(emptyVao_.id());
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commandBuffer_.id());
  glDrawArraysIndirect(GL_LINES, nullptr);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

}  // namespace sandstorm
