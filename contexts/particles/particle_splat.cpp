#include "contexts/particles/particle_splat.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdlib>
#include <string_view>

#include "contexts/particles/particle_backend.h"
#include "contexts/render/view_targets.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr std::size_t kChannels = 8;  // kSplatStride of splat_common.glsl
constexpr int kTile = 16;             // kSplatTile

// Storage-buffer bindings of the splat shaders.
enum Binding : GLuint {
  kPositionLife = 0,
  kVelocityKind = 1,
  kCounts = 4,
  kDispatch = 5,
  kAccumulation = 6,
  kTileCounts = 7,
  kTileLists = 8,
  kTileStarts = 9
};

}  // namespace

ParticleSplat::ParticleSplat()
    : tiled_(std::getenv("SANDSTORM_SPLAT") &&
             std::string_view(std::getenv("SANDSTORM_SPLAT")) == "tiled"),
      prepare_(std::vector<std::string>{"splat_prepare.comp"}),
      dispatch_(gl::createBuffer()) {
  glNamedBufferStorage(dispatch_.id(), 32, nullptr, 0);
  if (tiled_) {
    count_.emplace(gl::ProgramDesc{{"splat_bin.comp"}, {"COUNT"}, {}});
    scatter_.emplace(std::vector<std::string>{"splat_bin.comp"});
    scan_.emplace(std::vector<std::string>{"splat_scan.comp"});
    tile_.emplace(std::vector<std::string>{"splat_tile.comp"});
  } else {
    splat_.emplace(std::vector<std::string>{"particle_splat.comp"});
    resolve_.emplace(std::vector<std::string>{"particle_splat_resolve.comp"});
  }
}

void ParticleSplat::draw(const ParticleBackend& particles, const ViewTargets& targets,
                         std::uint32_t sprite) const {
  const ParticleBackend::Records records = particles.records();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPositionLife, records.positionLife);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVelocityKind, records.velocityKind);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCounts, records.countBuffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDispatch, dispatch_.id());
  glBindTextureUnit(2, sprite);
  glBindTextureUnit(3, targets.sceneDepth());
  glBindImageTexture(0, targets.particleColor(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glBindImageTexture(1, targets.particleNormal(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);

  prepare_.use();
  glProgramUniform1ui(prepare_.id(), 0, records.countOffset / 4);
  glProgramUniform1ui(prepare_.id(), 1, records.countAdd);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);

  if (tiled_)
    drawTiled(targets, particles.capacity());
  else
    drawAtomic(targets);
  // ParticlePost reads the images as textures; the next view starts from zeroed sums.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                  GL_SHADER_STORAGE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

void ParticleSplat::drawAtomic(const ViewTargets& targets) const {
  const glm::ivec2 size = targets.size();
  const std::size_t pixels = std::size_t(size.x) * std::size_t(size.y);
  if (pixels > pixels_) {
    accumulation_ = gl::createBuffer();
    glGetError();
    glNamedBufferStorage(accumulation_.id(), GLsizeiptr(pixels * kChannels * 4), nullptr, 0);
    if (glGetError() == GL_OUT_OF_MEMORY)
      throw Error(concat("ParticleSplat: no GPU memory for ", pixels, " pixels"));
    const GLuint zero = 0;
    glClearNamedBufferData(accumulation_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    pixels_ = pixels;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kAccumulation, accumulation_.id());
  splat_->use();
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, dispatch_.id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  resolve_->use();
  glProgramUniform2i(resolve_->id(), 0, size.x, size.y);
  glDispatchCompute(GLuint((size.x + 15) / 16), GLuint((size.y + 15) / 16), 1);
}

void ParticleSplat::drawTiled(const ViewTargets& targets, std::size_t capacity) const {
  const glm::ivec2 size = targets.size();
  const glm::ivec2 tiles((size.x + kTile - 1) / kTile, (size.y + kTile - 1) / kTile);
  const std::size_t tileCount = std::size_t(tiles.x) * std::size_t(tiles.y);
  // A particle of at most 4 pixels covers at most 4 tiles, and most cover one:
  // three list entries a particle leave room; entries past the end are dropped.
  const std::size_t listCapacity = std::max<std::size_t>(3 * capacity, 4096);
  if (tileCount > tiles_) {
    tileCounts_ = gl::createBuffer();
    tileStarts_ = gl::createBuffer();
    glNamedBufferStorage(tileCounts_.id(), GLsizeiptr(tileCount * 4), nullptr, 0);
    glNamedBufferStorage(tileStarts_.id(), GLsizeiptr((tileCount + 1) * 4), nullptr, 0);
    tiles_ = tileCount;
  }
  if (listCapacity > listCapacity_) {
    tileLists_ = gl::createBuffer();
    glGetError();
    glNamedBufferStorage(tileLists_.id(), GLsizeiptr(listCapacity * 4), nullptr, 0);
    if (glGetError() == GL_OUT_OF_MEMORY)
      throw Error(
          concat("ParticleSplat: no GPU memory for the tile lists of ", capacity, " particles"));
    listCapacity_ = listCapacity;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileCounts, tileCounts_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileLists, tileLists_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileStarts, tileStarts_.id());
  const GLuint zero = 0;
  glClearNamedBufferSubData(tileCounts_.id(), GL_R32UI, 0, GLsizeiptr(tileCount * 4),
                            GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, dispatch_.id());
  count_->use();
  glProgramUniform2i(count_->id(), 0, tiles.x, tiles.y);
  glProgramUniform1ui(count_->id(), 1, GLuint(listCapacity_));
  glDispatchComputeIndirect(0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  scan_->use();
  glProgramUniform1ui(scan_->id(), 0, GLuint(tileCount));
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  scatter_->use();
  glProgramUniform2i(scatter_->id(), 0, tiles.x, tiles.y);
  glProgramUniform1ui(scatter_->id(), 1, GLuint(listCapacity_));
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  tile_->use();
  glProgramUniform2i(tile_->id(), 0, tiles.x, tiles.y);
  glProgramUniform1ui(tile_->id(), 1, GLuint(listCapacity_));
  glDispatchCompute(GLuint(tiles.x), GLuint(tiles.y), 1);
}

}  // namespace sandstorm
