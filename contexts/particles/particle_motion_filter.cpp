#include "contexts/particles/particle_motion_filter.h"

#include <epoxy/gl.h>

#include "contexts/gl/out_of_memory.h"
#include "contexts/render/view_targets.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr int kCell = 8;         // particle_motion_field.comp
constexpr int kMotionTile = 16;  // particle_motion_reach.comp
constexpr int kLevelsUniform = 15;

gl::Texture texture2D(GLenum format, glm::ivec2 size, GLenum filter) {
  gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, format, size.x, size.y);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GLint(filter));
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GLint(filter));
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

}  // namespace

ParticleMotionFilter::ParticleMotionFilter()
    : field_({"particle_motion_field.comp"}),
      reach_({"particle_motion_reach.comp"}),
      filter_({"particle_motion_filter.comp"}),
      shadowedFilter_({"particle_motion_filter.comp"}, {"SHADOWS"}) {}

void ParticleMotionFilter::resize(glm::ivec2 size) const {
  if (size == size_) return;
  const gl::OutOfMemoryCheck memory;
  // The filter samples the buffers and the motion field between their texels.
  color_ = texture2D(GL_RGBA16F, size, GL_LINEAR);
  normal_ = texture2D(GL_RGBA16F, size, GL_LINEAR);
  light_ = texture2D(GL_R16F, size, GL_LINEAR);
  cells_ = texture2D(GL_RGBA16F, (size + kCell - 1) / kCell, GL_LINEAR);
  reachTexture_ = texture2D(GL_RG16F, (size + kMotionTile - 1) / kMotionTile, GL_NEAREST);
  if (memory.failed())
    throw Error(concat("the GPU is out of memory for motion blur's images of ", size.x, "x", size.y,
                       " pixels; set render.shutter = 0 or choose a smaller wall"));
  size_ = size;
}

void ParticleMotionFilter::bindResolveImages(glm::ivec2 size) const {
  resize(size);
  glBindImageTexture(0, color_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glBindImageTexture(1, normal_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glBindImageTexture(2, light_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R16F);
}

void ParticleMotionFilter::apply(const ViewTargets& targets, int levels, bool shadows) const {
  const glm::ivec2 size = targets.size();
  if (size != size_) throw Error("ParticleMotionFilter: apply() for another size than resolved");
  const glm::ivec2 cells = (size + kCell - 1) / kCell,
                   tiles = (size + kMotionTile - 1) / kMotionTile;
  glBindImageTexture(3, cells_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  field_.use();
  glProgramUniform2i(field_.id(), 0, size.x, size.y);
  glProgramUniform1i(field_.id(), kLevelsUniform, levels);
  glDispatchCompute(GLuint((cells.x + 7) / 8), GLuint((cells.y + 7) / 8), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);

  glBindTextureUnit(3, cells_.id());
  glBindImageTexture(5, reachTexture_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG16F);
  reach_.use();
  glProgramUniform2i(reach_.id(), 0, size.x, size.y);
  glDispatchCompute(GLuint((tiles.x + 7) / 8), GLuint((tiles.y + 7) / 8), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);

  const gl::Program& filter = shadows ? shadowedFilter_ : filter_;
  glBindTextureUnit(0, color_.id());
  glBindTextureUnit(1, normal_.id());
  glBindTextureUnit(2, light_.id());
  glBindTextureUnit(5, reachTexture_.id());
  glBindImageTexture(0, targets.particleColor(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glBindImageTexture(1, targets.particleNormal(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glBindImageTexture(2, targets.particleLight(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R16F);
  filter.use();
  glProgramUniform2i(filter.id(), 0, size.x, size.y);
  glDispatchCompute(GLuint((size.x + 15) / 16), GLuint((size.y + 15) / 16), 1);
}

}  // namespace sandstorm
