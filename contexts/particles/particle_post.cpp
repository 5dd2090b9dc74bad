#include "contexts/particles/particle_post.h"

#include <epoxy/gl.h>

#include "contexts/render/view_targets.h"

namespace sandstorm {

ParticlePost::ParticlePost()
    : composite_(std::vector<std::string>{"fullscreen.vert", "particle_post.frag"}),
      emptyVao_(gl::createVertexArray()) {}

void ParticlePost::draw(const ViewTargets& targets, std::uint32_t destination,
                        glm::ivec2 origin) const {
  glBindFramebuffer(GL_FRAMEBUFFER, destination);
  glViewport(origin.x, origin.y, targets.size().x, targets.size().y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDepthMask(GL_FALSE);
  glBindTextureUnit(0, targets.sceneColor());
  glBindTextureUnit(1, targets.particleColor());
  glBindTextureUnit(2, targets.particleNormal());
  glBindTextureUnit(3, targets.particleLight());
  glBindTextureUnit(4, targets.sceneDepth());
  composite_.use();
  glProgramUniform2i(composite_.id(), 0, origin.x, origin.y);
  glBindVertexArray(emptyVao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

}  // namespace sandstorm
