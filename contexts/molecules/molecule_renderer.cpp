#include "contexts/molecules/molecule_renderer.h"

#include <epoxy/gl.h>

#include "contexts/render/view_targets.h"

namespace sandstorm {

MoleculeRenderer::MoleculeRenderer()
    : program_(std::vector<std::string>{"molecule_render.vert", "molecule_render.frag"}),
      empty_(gl::createVertexArray()) {}

void MoleculeRenderer::draw(const MoleculeUpdate& molecules, std::uint32_t moleculeBlock,
                            const ViewTargets& targets) const {
  const MoleculeUpdate::Records r = molecules.records();
  if (r.members == 0 || r.positionLife == 0 || moleculeBlock == 0) return;
  glBindFramebuffer(GL_FRAMEBUFFER, targets.particleFramebuffer());
  glViewport(0, 0, targets.size().x, targets.size().y);
  glDisable(GL_DEPTH_TEST);  // the fragment stage tests against the scene's depth itself
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glBindTextureUnit(3, targets.sceneDepth());
  glBindBufferBase(GL_UNIFORM_BUFFER, 5, moleculeBlock);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, r.positionLife);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, r.velocityKind);
  program_.use();
  glBindVertexArray(empty_.id());
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, r.control);
  glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(std::uintptr_t(r.drawOffset)));
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindVertexArray(0);
  glDisable(GL_BLEND);
}

}  // namespace sandstorm
