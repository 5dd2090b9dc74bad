#include "contexts/particles/particle_post.h"

#include <epoxy/gl.h>

#include "contexts/render/view_targets.h"

namespace sandstorm {
namespace {

// The texture behind a framebuffer's first colour attachment where it is an
// RGBA8 texture (an offscreen wall's image, an anaglyph eye): 0 otherwise
// (a window's framebuffer, a renderbuffer).
GLuint rgba8Texture(GLuint framebuffer) {
  if (framebuffer == 0) return 0;
  GLint type = GL_NONE, name = 0;
  glGetNamedFramebufferAttachmentParameteriv(framebuffer, GL_COLOR_ATTACHMENT0,
                                             GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  if (type != GL_TEXTURE) return 0;
  glGetNamedFramebufferAttachmentParameteriv(framebuffer, GL_COLOR_ATTACHMENT0,
                                             GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
  GLint format = 0;
  glGetTextureLevelParameteriv(GLuint(name), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  return format == GL_RGBA8 ? GLuint(name) : 0;
}

}  // namespace

bool ParticlePost::computes(std::uint32_t destination) {
  return rgba8Texture(destination) != 0;
}

ParticlePost::ParticlePost()
    : composite_(std::vector<std::string>{"fullscreen.vert", "particle_post.frag"}),
      computeComposite_(std::vector<std::string>{"particle_post.comp"}),
      emptyVao_(gl::createVertexArray()) {}

void ParticlePost::draw(const ViewTargets& targets, std::uint32_t destination,
                        glm::ivec2 origin) const {
  glBindTextureUnit(0, targets.sceneColor());
  glBindTextureUnit(1, targets.particleColor());
  glBindTextureUnit(2, targets.particleNormal());
  glBindTextureUnit(3, targets.particleLight());
  glBindTextureUnit(4, targets.sceneDepth());
  const glm::ivec2 size = targets.size();
  if (const GLuint image = rgba8Texture(destination)) {
    computeComposite_.use();
    glProgramUniform2i(computeComposite_.id(), 0, origin.x, origin.y);
    glBindImageTexture(0, image, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glDispatchCompute(GLuint((size.x + 15) / 16), GLuint((size.y + 15) / 16), 1);
    // What follows reads the image (stereo composition, the menu, captures).
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    return;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, destination);
  glViewport(origin.x, origin.y, size.x, size.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDepthMask(GL_FALSE);
  composite_.use();
  glProgramUniform2i(composite_.id(), 0, origin.x, origin.y);
  glBindVertexArray(emptyVao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

}  // namespace sandstorm
