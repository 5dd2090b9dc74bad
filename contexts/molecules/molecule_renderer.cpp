#include "contexts/molecules/molecule_renderer.h"

#include <epoxy/gl.h>

#include "contexts/render/view_targets.h"

namespace sandstorm {

MoleculeRenderer::MoleculeRenderer()
    : program_(std::vector<std::string>{"molecule_render.vert", "molecule_render.frag"}),
      empty_(gl::createVertexArray()) {}

void MoleculeRenderer::draw(const MoleculeHandles& r, const ViewTargets& targets) const {
  if (!r) return;
  glBindFramebuffer(GL_FRAMEBUFFER, targets.particleFramebuffer());
  glViewport(0, 0, targets.size().x, targets.size().y);
  glDisable(GL_DEPTH_TEST);  // the fragment stage tests against the scene's depth itself
  glDepthMask(GL_FALSE);
  // A closed solid (the tetrahedron) shows its outward faces only: they wind
  // counter-clockwise seen from outside (MoleculeShape).
  if (r.members == 4) {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
  } else {
    glDisable(GL_CULL_FACE);
  }
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glBindTextureUnit(3, targets.sceneDepth());
  glBindBufferBase(GL_UNIFORM_BUFFER, 5, r.block);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, r.positionLife);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, r.velocityKind);
  program_.use();
  glBindVertexArray(empty_.id());
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, r.control);
  glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(std::uintptr_t(r.drawOffset)));
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindVertexArray(0);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
}

std::vector<Particle> readMolecules(const MoleculeHandles& m) {
  if (!m) return {};
  gl::Buffer staging = gl::createBuffer();
  glNamedBufferStorage(staging.id(), 4, nullptr, GL_DYNAMIC_STORAGE_BIT | GL_CLIENT_STORAGE_BIT);
  glCopyNamedBufferSubData(m.control, staging.id(), m.countOffset, 0, 4);
  std::uint32_t count = 0;
  glGetNamedBufferSubData(staging.id(), 0, 4, &count);
  const std::size_t n = std::size_t(m.members), stride = m.stride;
  std::vector<Particle> out(std::size_t(count) * n);
  if (count == 0) return out;
  // Each member's slice of `count` records into one buffer: positions, then velocities.
  const GLsizeiptr slice = GLsizeiptr(count * sizeof(glm::vec4));
  gl::Buffer copy = gl::createBuffer();
  glNamedBufferStorage(copy.id(), 2 * GLsizeiptr(n) * slice, nullptr, GL_CLIENT_STORAGE_BIT);
  for (std::size_t j = 0; j < n; ++j) {
    const GLintptr from = GLintptr(j * stride * sizeof(glm::vec4));
    glCopyNamedBufferSubData(m.positionLife, copy.id(), from, GLintptr(j) * slice, slice);
    glCopyNamedBufferSubData(m.velocityKind, copy.id(), from, GLintptr(n + j) * slice, slice);
  }
  std::vector<glm::vec4> data(2 * n * count);
  glGetNamedBufferSubData(copy.id(), 0, 2 * GLsizeiptr(n) * slice, data.data());
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t j = 0; j < n; ++j)
      out[i * n + j] = Particle{data[j * count + i], data[(n + j) * count + i]};
  return out;
}

}  // namespace sandstorm
