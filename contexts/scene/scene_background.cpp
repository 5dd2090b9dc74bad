#include "contexts/scene/scene_background.h"

#include <epoxy/gl.h>

#include <algorithm>

#include "contexts/render/view_targets.h"

namespace sandstorm {

SceneBackground::SceneBackground() : program_(std::vector<std::string>{"scene_background.comp"}) {}

void SceneBackground::draw(const ViewTargets& targets, const std::optional<FlatGround>& ground,
                           bool items, std::span<const WindowSegment> lines,
                           glm::vec3 lineColor) const {
  program_.use();
  const FlatGround g = ground.value_or(FlatGround{});
  glProgramUniform4f(program_.id(), 0, g.min.x, g.min.y, g.max.x, g.max.y);
  glProgramUniform1f(program_.id(), 1, g.height);
  glProgramUniform1i(program_.id(), 2, ground ? GL_TRUE : GL_FALSE);
  glProgramUniform1i(program_.id(), 3, items ? GL_TRUE : GL_FALSE);
  const int count = int(std::min<std::size_t>(lines.size(), kMaxLines));
  glProgramUniform1i(program_.id(), 4, count);
  glProgramUniform3f(program_.id(), 5, lineColor.x, lineColor.y, lineColor.z);
  for (int i = 0; i < count; ++i) {
    const WindowSegment& s = lines[std::size_t(i)];
    glProgramUniform3f(program_.id(), 6 + i, s.a.x, s.a.y, s.a.z);
    glProgramUniform3f(program_.id(), 6 + kMaxLines + i, s.b.x, s.b.y, s.b.z);
  }
  glBindTextureUnit(3, targets.itemsDepth());
  glBindImageTexture(0, targets.sceneColor(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glBindImageTexture(1, targets.sceneDepth(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  const glm::ivec2 size = targets.size();
  glDispatchCompute(GLuint((size.x + 15) / 16), GLuint((size.y + 15) / 16), 1);
  // Raster items blend over the colour after; the particle passes sample both.
  glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                  GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace sandstorm
