#include "contexts/particles/particle_splat.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string_view>

#include "contexts/gl/out_of_memory.h"
#include "contexts/particles/particle_backend.h"
#include "contexts/render/view_targets.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr std::size_t kChannels = 8;          // kSplatStride of splat_common.glsl
constexpr int kTile = 32;                     // kSplatTile
constexpr std::size_t kMaxTiles = 8192;       // kSplatMaxTiles
constexpr std::size_t kMaxBinGroups = 1024;   // kSplatMaxBinGroups
constexpr std::size_t kRecordBytes = 16;      // a splat record (splat_footprint.glsl)
constexpr int kLevels = 4;                    // kSplatLevels
constexpr GLint kLevelsUniform = 15;          // uSplatLevels (splat_footprint.glsl)
constexpr std::size_t kMotionTileBytes = 32;  // kSplatMotionStride ints (splat_common.glsl)

// The levels' grids, as splat_common.glsl lays them out: each level's pixels
// and tiles follow the finer levels'.
glm::ivec2 levelSize(glm::ivec2 size, int level) {
  return (size + (1 << level) - 1) >> level;
}
std::size_t levelPixels(glm::ivec2 size, int levels) {
  std::size_t pixels = 0;
  for (int l = 0; l < levels; ++l) {
    const glm::ivec2 s = levelSize(size, l);
    pixels += std::size_t(s.x) * std::size_t(s.y);
  }
  return pixels;
}
std::size_t levelTiles(glm::ivec2 size, int levels) {
  std::size_t tiles = 0;
  for (int l = 0; l < levels; ++l) {
    const glm::ivec2 t = (levelSize(size, l) + kTile - 1) / kTile;
    tiles += std::size_t(t.x) * std::size_t(t.y);
  }
  return tiles;
}

// Storage-buffer bindings of the splat shaders.
enum Binding : GLuint {
  kPositionLife = 0,
  kVelocityKind = 1,
  kCounts = 4,
  kDispatch = 5,
  kAccumulation = 6,
  kTileCounts = 7,
  kTileLists = 8,
  kTileStarts = 9,
  kGroupBase = 10,
  kChunkStarts = 11,
  kChunkDispatch = 12,
  kTrailDispatch = 13,
  kOccupied = 14,
  kTrailRing = 15,
  kMotionSums = 16,
  kTrailStaged = 17,
  kInView = 18,
  kInViewCount = 19,
  kNextInView = 20
};
constexpr GLuint kNextViewBlock = 7;  // splat_bin.comp's NextViewBlock
constexpr GLint kNextListUniform = 3;

bool sameParticles(const ParticleBackend::Records& a, const ParticleBackend::Records& b) {
  return a.positionLife == b.positionLife && a.velocityKind == b.velocityKind &&
         a.countBuffer == b.countBuffer && a.countOffset == b.countOffset &&
         a.countAdd == b.countAdd;
}

// Uniform locations of trail_common.glsl.
constexpr GLint kTrailLengthUniform = 16, kTrailHeadUniform = 17;

gl::Buffer allocate(std::size_t bytes, const char* what) {
  gl::Buffer buffer = gl::createBuffer();
  const gl::OutOfMemoryCheck memory;
  glNamedBufferStorage(buffer.id(), GLsizeiptr(bytes), nullptr, 0);
  if (memory.failed())
    throw Error(concat("the GPU has no memory for ", what, " (", bytes >> 20,
                       " MiB); lower sim.maximum, or choose a smaller wall"));
  return buffer;
}

void zero(const gl::Buffer& buffer) {
  const GLuint value = 0;
  glClearNamedBufferData(buffer.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &value);
}

}  // namespace

ParticleSplat::ParticleSplat(const GpuTuning& tuning)
    : tiled_(tuning.splat == GpuTuning::Splat::Tiled),
      trailTuning_(tuning.trailPass),
      // Records a chunk: 16 an invocation; tiles with more spread over
      // several workgroups. Tests make them small to put several in a tile.
      chunk_(GLuint(tuning.splatChunk)),
      // Records the lists hold (0: two a particle of capacity); tests make it small.
      listRecords_(tuning.splatList),
      prepare_(std::vector<std::string>{"splat_prepare.comp"}),
      clear_(std::vector<std::string>{"splat_clear.comp"}),
      dispatch_(gl::createBuffer()),
      chunkDispatch_(gl::createBuffer()),
      nextViewBlock_(gl::createBuffer()) {
  glNamedBufferStorage(dispatch_.id(), 64, nullptr, 0);
  glNamedBufferStorage(nextViewBlock_.id(), sizeof(ViewBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  // A storage buffer may hold at most GL_MAX_SHADER_STORAGE_BLOCK_SIZE bytes
  // (2 GB on NVIDIA's driver: 134 million records); the scatter pass adds
  // the records past the lists' end itself.
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  maxListRecords_ = std::size_t(std::max<GLint64>(maxBlock, 1 << 20)) / kRecordBytes;
  glNamedBufferStorage(chunkDispatch_.id(), 32, nullptr, 0);
  if (tiled_) scan_.emplace(std::vector<std::string>{"splat_scan.comp"});
  programs({});  // the plain look's, up front (compile errors show at once)
}

namespace {

std::vector<std::string> lookDefines(SplatLook look) {
  std::vector<std::string> defines;
  if (look.shadows) defines.push_back("SHADOWS");
  if (look.blur == SplatLook::Blur::Smear) defines.push_back("MOTION_BLUR");
  if (look.blur == SplatLook::Blur::Filter) defines.push_back("MOTION_FILTER");
  return defines;
}

}  // namespace

const ParticleSplat::Programs& ParticleSplat::programs(SplatLook look) const {
  std::unique_ptr<Programs>& p = variants_[look.shadows][int(look.blur)];
  if (!p) {
    const std::vector<std::string> d = lookDefines(look);
    p = std::make_unique<Programs>(Programs{gl::Program({"particle_splat.comp"}, d),
                                            gl::Program({"particle_splat_resolve.comp"}, d),
                                            std::nullopt, std::nullopt});
    if (tiled_) {
      p->bin.emplace(std::vector<std::string>{"splat_bin.comp"}, d);
      p->tile.emplace(std::vector<std::string>{"splat_tile.comp"}, d);
    }
  }
  return *p;
}

void ParticleSplat::draw(const ParticleBackend& particles, const ViewTargets& targets,
                         std::uint32_t sprite, SplatLook look, SplatViews views) const {
  const Programs& p = programs(look);
  const ParticleBackend::Records records = particles.records();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPositionLife, records.positionLife);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVelocityKind, records.velocityKind);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCounts, records.countBuffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDispatch, dispatch_.id());
  glBindTextureUnit(2, sprite);
  glBindTextureUnit(3, targets.sceneDepth());
  glBindImageTexture(0, targets.particleColor(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glBindImageTexture(1, targets.particleNormal(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glBindImageTexture(2, targets.particleLight(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R16F);

  const glm::ivec2 size = targets.size();
  const bool filter = look.blur == SplatLook::Blur::Filter;
  // Levels where asked for; where their tiles overflow the histogram (views
  // of more than about 6 megapixels) the tiled pass draws every splat at
  // full resolution, as it did before levels, rather than falling back to
  // the much slower atomic pass.
  int levels = look.levels ? kLevels : 1;
  const bool tiled = tiled_ && levelTiles(size, 1) <= kMaxTiles;
  if (tiled && levelTiles(size, levels) > kMaxTiles) levels = 1;
  bindSums(levelPixels(size, levels));
  if (filter) bindMotionSums(levelTiles(size, levels));
  // The coarser levels' tiles that get splats (splat_occupied.glsl).
  const std::size_t occupancy = levels > 1 ? levelTiles(size, levels) : 0;
  if (occupancy > occupancy_) {
    occupied_ = allocate(occupancy * 4, "the splat tiles' marks");
    zero(occupied_);
    occupancy_ = occupancy;
  }
  if (occupancy > 0) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kOccupied, occupied_.id());
  for (const gl::Program* program : {&p.splat, &p.resolve})
    glProgramUniform1i(program->id(), kLevelsUniform, levels);

  prepare(records);
  const bool trails = hasTrails(records);
  if (tiled) {
    const std::size_t tiles = levelTiles(size, levels);
    addTiled(p, tiles, levels, listRecords(particles.capacity(), trails ? records.trailLength : 0),
             particles.capacity(), nextList(records, views, size, tiles, particles.capacity()));
  } else {
    nextListed_.reset();
    addAtomic(p);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  if (trails) addTrailSums(records, particles.capacity(), size, tiled);
  // Both variants leave the sums in the buffer; the resolve turns them into
  // the particle images and zeroes the full-resolution ones for the next view.
  // With the filter, into its own images, which it then blurs into the view's.
  if (filter) {
    if (!filter_) filter_ = std::make_unique<ParticleMotionFilter>();
    filter_->bindResolveImages(size);
  }
  p.resolve.use();
  glProgramUniform2i(p.resolve.id(), 0, size.x, size.y);
  glDispatchCompute(GLuint((size.x + 15) / 16), GLuint((size.y + 15) / 16), 1);
  if (filter) {
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    filter_->apply(targets, levels, look.shadows);
    // The tiles' motion sums, a few bytes a tile, are zeroed for the next view at once.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    const GLuint value = 0;
    glClearNamedBufferSubData(motion_.id(), GL_R32UI, 0,
                              GLsizeiptr(levelTiles(size, levels) * kMotionTileBytes),
                              GL_RED_INTEGER, GL_UNSIGNED_INT, &value);
  }
  // ParticlePost reads the images as textures.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                  GL_SHADER_STORAGE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  // The coarser levels' sums, which many pixels read, are zeroed after the
  // resolve where marked, and so are the marks.
  if (levels > 1) {
    clear_.use();
    glProgramUniform1i(clear_.id(), kLevelsUniform, levels);
    glDispatchCompute(GLuint(occupancy - levelTiles(size, 1)), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
}

bool ParticleSplat::hasTrails(const ParticleBackend::Records& r) {
  return r.trails != 0 && r.trailLength >= 2;
}

void ParticleSplat::bindSums(std::size_t pixels) const {
  if (pixels > pixels_) {
    accumulation_ = allocate(pixels * kChannels * 4, "the splat sums");
    zero(accumulation_);
    pixels_ = pixels;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kAccumulation, accumulation_.id());
}

void ParticleSplat::bindMotionSums(std::size_t tiles) const {
  if (tiles > motionTiles_) {
    motion_ = allocate(tiles * kMotionTileBytes, "motion blur's sums");
    zero(motion_);
    motionTiles_ = tiles;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMotionSums, motion_.id());
}

void ParticleSplat::prepare(const ParticleBackend::Records& records) const {
  prepare_.use();
  glProgramUniform1ui(prepare_.id(), 0, records.countOffset / 4);
  glProgramUniform1ui(prepare_.id(), 1, records.countAdd);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

void ParticleSplat::addTrailSums(const ParticleBackend::Records& records, std::size_t capacity,
                                 glm::ivec2 size, bool tiled) const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTrailRing, records.trails);
  const FasterChoice::Run pass = tiled ? trailPass() : FasterChoice::Run{kAtomicTrails, -1};
  if (pass.ticket >= 0) trailSpans_.begin(pass.ticket);
  if (pass.way == kTiledTrails)
    addTiledTrails(records, levelTiles(size, 1));
  else
    addTrails(records, capacity);
  if (pass.ticket >= 0) trailSpans_.end();
}

// Trails in a view that draws billboards: the same passes as with splats,
// into the trails' two sums alone, which trail_over_scene.comp then blends
// over the scene's colour, unlit, where GL lines were (4.3 times the frame
// in the bench's billboard views) and zeroes.
void ParticleSplat::drawTrailsOverScene(const ParticleBackend& particles,
                                        const ViewTargets& targets) const {
  const ParticleBackend::Records records = particles.records();
  if (!hasTrails(records)) return;
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPositionLife, records.positionLife);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVelocityKind, records.velocityKind);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCounts, records.countBuffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDispatch, dispatch_.id());
  glBindTextureUnit(3, targets.sceneDepth());
  const glm::ivec2 size = targets.size();
  const bool tiled = tiled_ && levelTiles(size, 1) <= kMaxTiles;
  bindSums(levelPixels(size, 1));
  prepare(records);
  if (tiled) bindTiles(levelTiles(size, 1), listRecords(particles.capacity(), records.trailLength));
  addTrailSums(records, particles.capacity(), size, tiled);
  if (!trailOverScene_)
    trailOverScene_ =
        std::make_unique<gl::Program>(std::vector<std::string>{"trail_over_scene.comp"});
  // The scene's colour was drawn by the raster pipeline, which needs no barrier.
  glBindImageTexture(0, targets.sceneColor(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
  trailOverScene_->use();
  glProgramUniform2i(trailOverScene_->id(), 0, size.x, size.y);
  glDispatchCompute(GLuint((size.x + 15) / 16), GLuint((size.y + 15) / 16), 1);
  // The scene's next items draw into it; the composite reads it as a texture.
  glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                  GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

namespace {

void setTrailUniforms(const gl::Program& program, const ParticleBackend::Records& r) {
  glProgramUniform1i(program.id(), kTrailLengthUniform, r.trailLength);
  glProgramUniform1i(program.id(), kTrailHeadUniform, r.trailHead);
}

}  // namespace

// Trails (render.trail_length) join the splats in the same sums: drawn by
// compute, like the particles, where GL lines were 17 times slower on an
// H100 (docs/PERFORMANCE.md). This is the atomic variant, one invocation a
// segment; addTiledTrails adds the same integers.
void ParticleSplat::addTrails(const ParticleBackend::Records& r, std::size_t capacity) const {
  if (!trailPrepare_) {
    trailPrepare_ = std::make_unique<gl::Program>(std::vector<std::string>{"trail_dispatch.comp"});
    trails_ = std::make_unique<gl::Program>(std::vector<std::string>{"trail_splat.comp"});
    trailDispatch_ = gl::createBuffer();
    glNamedBufferStorage(trailDispatch_.id(), 16, nullptr, 0);
  }
  const gl::Program& trails = *trails_;
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTrailDispatch, trailDispatch_.id());
  trailPrepare_->use();
  glProgramUniform1ui(trailPrepare_->id(), 0, r.countOffset / 4);
  glProgramUniform1ui(trailPrepare_->id(), 1, r.countAdd);
  glProgramUniform1ui(trailPrepare_->id(), 2, GLuint(r.trailLength - 1));
  glProgramUniform1ui(trailPrepare_->id(), 3, GLuint(capacity));
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  trails.use();
  setTrailUniforms(trails, r);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, trailDispatch_.id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

// The tiled variant: the splats' bins, lists and chunks again (addTiled has
// finished with them), for runs of trail pixels in the full-resolution
// tiles (trail_bin.comp, trail_tile.comp), so a pixel costs shared-memory
// atomics, not global ones. The trails are walked once: the runs wait in
// a staging buffer for the scan to say where their tiles' lists start.
void ParticleSplat::addTiledTrails(const ParticleBackend::Records& r, std::size_t tileCount) const {
  if (!trailBin_) {
    trailBin_ = std::make_unique<gl::Program>(std::vector<std::string>{"trail_bin.comp"});
    trailTile_ = std::make_unique<gl::Program>(std::vector<std::string>{"trail_tile.comp"});
  }
  // Runs are 8 bytes, half a splat record: the lists hold twice as many;
  // [gpu] splat_list caps them as it caps the splats.
  const std::size_t runs =
      listRecords_ ? std::min(listRecords_, 2 * listCapacity_) : 2 * listCapacity_;
  const GLuint runCapacity =
      GLuint(std::min<std::size_t>(runs, std::numeric_limits<GLuint>::max()));
  // The staged runs: as many again as the lists hold and half as many more,
  // shared by the binning workgroups (a share's overflow adds itself), three
  // words each, then a count a workgroup; capped at what one buffer holds
  // and at what the shader's 32-bit word indices reach.
  const std::size_t words =
      std::min<std::size_t>(maxListRecords_ * kRecordBytes / 4, std::numeric_limits<GLuint>::max());
  const std::size_t stage =
      std::min<std::size_t>(std::size_t(runCapacity) * 3 / 2, (words - kMaxBinGroups) / 3);
  const std::size_t stageBytes = (stage * 3 + kMaxBinGroups) * 4;
  if (stageBytes > trailStagedBytes_) {
    trailStaged_ = allocate(stageBytes, "the trails' staged runs");
    trailStagedBytes_ = stageBytes;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTrailStaged, trailStaged_.id());
  const gl::Program &bin = *trailBin_, &tile = *trailTile_;
  glProgramUniform1ui(bin.id(), 3, GLuint(stage));
  for (const gl::Program* program : {&bin, &tile}) {
    setTrailUniforms(*program, r);
    glProgramUniform1ui(program->id(), 2, runCapacity);
  }
  // Stage: the one walk along the trails, runs staged with their tile and rank.
  constexpr GLintptr kBinDispatch = 32;  // as addTiled's
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, dispatch_.id());
  bin.use();
  glProgramUniform1i(bin.id(), 1, GL_FALSE);
  glDispatchComputeIndirect(kBinDispatch);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  scan_->use();
  glProgramUniform1ui(scan_->id(), 0, GLuint(tileCount));
  // A run is several splats' work: chunks of a quarter as many runs spread
  // the tornado's dense tiles wider (on an H100 2048 took 0.96 times as
  // long as 8192, 32768 1.6 times).
  const GLuint chunk = std::max<GLuint>(chunk_ / 4, 1);
  glProgramUniform1ui(scan_->id(), 1, chunk);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);

  // Place: the staged runs copied into their tiles' lists.
  glProgramUniform1i(bin.id(), 1, GL_TRUE);
  bin.use();
  glDispatchComputeIndirect(kBinDispatch);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  tile.use();
  glProgramUniform1ui(tile.id(), 1, chunk);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, chunkDispatch_.id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

FasterChoice::Run ParticleSplat::trailPass() const {
  switch (trailTuning_) {
    case GpuTuning::TrailPass::Tiled:
      return {kTiledTrails, -1};
    case GpuTuning::TrailPass::Atomic:
      return {kAtomicTrails, -1};
    case GpuTuning::TrailPass::Auto:
      break;
  }
  for (const auto& [ticket, ms] : trailSpans_.poll())
    trailChoice_.measured(ticket, ms);
  return trailChoice_.next();
}

void ParticleSplat::addAtomic(const Programs& p) const {
  p.splat.use();
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, dispatch_.id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

std::size_t ParticleSplat::listRecords(std::size_t capacity, int trailLength) const {
  // [gpu] splat_list sets the number; a storage buffer holds at most maxListRecords_.
  if (listRecords_ != 0) return std::min(listRecords_, maxListRecords_);
  // A particle of a few pixels covers one 32-pixel tile, sometimes two or
  // four; a trail of a few pixels a segment makes about one run of pixels in
  // a tile (8 bytes, half a record) every four segments. The scatter passes
  // add those past the end themselves.
  const std::size_t splats = 2 * capacity;
  const std::size_t runs = trailLength >= 2 ? capacity * std::size_t((trailLength + 2) / 4) / 2 : 0;
  return std::min(std::max(splats, runs) + 4096, maxListRecords_);
}

ParticleSplat::NextList ParticleSplat::nextList(const ParticleBackend::Records& records,
                                                SplatViews views, glm::ivec2 size,
                                                std::size_t tileCount,
                                                std::size_t particles) const {
  // Visit the list where the last draw made it for this very view and these particles.
  const std::optional<NextListed> listed = std::move(nextListed_);
  nextListed_.reset();
  NextList mode = NextList::None;
  if (listed && views.view && sameParticles(records, listed->records)) {
    const ViewBlock block = makeViewBlock(*views.view, size);
    if (std::memcmp(&block, &listed->view, sizeof block) == 0) mode = NextList::Visit;
  }
  // List for the next view where the histogram has a slot to count them in.
  if (mode == NextList::None && views.next && tileCount + 2 <= kMaxTiles) {
    mode = NextList::List;
    nextListed_ = NextListed{makeViewBlock(*views.next, size), records};
    glNamedBufferSubData(nextViewBlock_.id(), 0, sizeof(ViewBlock), &nextListed_->view);
  }
  // Both counts declare the list and the block: bound always, sized where used.
  const std::size_t words = kMaxBinGroups + (mode != NextList::None ? particles : 1);
  if (words > nextInViewCapacity_) {
    nextInView_ = allocate(words * 4, "the particles the next view may show");
    nextInViewCapacity_ = words;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kNextInView, nextInView_.id());
  glBindBufferBase(GL_UNIFORM_BUFFER, kNextViewBlock, nextViewBlock_.id());
  return mode;
}

void ParticleSplat::addTiled(const Programs& p, std::size_t tileCount, int levels,
                             std::size_t listCapacity, std::size_t particles, NextList next) const {
  bindTiles(tileCount, listCapacity);
  bindInView(particles);

  // The binning dispatch size is the second uvec4 of the prepare pass's output.
  constexpr GLintptr kBinDispatch = 32;
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, dispatch_.id());
  p.bin->use();
  glProgramUniform1i(p.bin->id(), kLevelsUniform, levels);
  glProgramUniform1i(p.bin->id(), 1, GL_FALSE);
  glProgramUniform1ui(p.bin->id(), 2, GLuint(listCapacity));
  glProgramUniform1i(p.bin->id(), kNextListUniform, int(next));
  glDispatchComputeIndirect(kBinDispatch);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  scan_->use();
  glProgramUniform1ui(scan_->id(), 0, GLuint(tileCount));
  glProgramUniform1ui(scan_->id(), 1, chunk_);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);

  glProgramUniform1i(p.bin->id(), 1, GL_TRUE);
  p.bin->use();
  glDispatchComputeIndirect(kBinDispatch);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  p.tile->use();
  glProgramUniform1i(p.tile->id(), kLevelsUniform, levels);
  glProgramUniform1ui(p.tile->id(), 1, chunk_);
  glProgramUniform1ui(p.tile->id(), 2, GLuint(listCapacity));
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, chunkDispatch_.id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

void ParticleSplat::bindInView(std::size_t particles) const {
  if (particles > inViewCapacity_) {
    inView_ = allocate(particles * 4, "the particles in view");
    inViewCapacity_ = particles;
  }
  if (!inViewCount_) inViewCount_ = allocate(kMaxBinGroups * 4, "the counts of particles in view");
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInView, inView_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInViewCount, inViewCount_.id());
}

void ParticleSplat::bindTiles(std::size_t tileCount, std::size_t listCapacity) const {
  if (tileCount > tiles_) {
    tileCounts_ = allocate(tileCount * 4, "the tile counts");
    zero(tileCounts_);  // splat_scan.comp zeroes them after each view
    tileStarts_ = allocate((tileCount + 1) * 4, "the tile starts");
    chunkStarts_ = allocate((tileCount + 1) * 4, "the chunk starts");
    groupBase_ = allocate(kMaxBinGroups * tileCount * 4, "the binning offsets");
    tiles_ = tileCount;
  }
  if (listCapacity > listCapacity_) {
    tileLists_ = allocate(listCapacity * kRecordBytes, "the tile lists");
    listCapacity_ = listCapacity;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileCounts, tileCounts_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileLists, tileLists_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileStarts, tileStarts_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kGroupBase, groupBase_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kChunkStarts, chunkStarts_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kChunkDispatch, chunkDispatch_.id());
}

}  // namespace sandstorm
