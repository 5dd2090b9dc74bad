// ParticleSplat: a compute-shader renderer for small particles (issue 6): it
// writes the same particle buffers ParticleRender's billboards write (the
// premultiplied colour and normal that ParticlePost lights), without the
// raster pipeline, which on datacenter GPUs tops out far below their compute.
//
// Each particle adds its billboard's footprint (same size, sprite, normal,
// colour, soft depth test against the scene: shaders/splat_footprint.glsl) to
// order-independent fixed-point sums per pixel, which a resolve turns into the
// particle buffers. Two variants add the same integers, so give the same image:
//   tiled (the default): bin the particles by 32x32-pixel tile (each
//     workgroup counts a range of particles in a histogram of all tiles in
//     shared memory; a prefix sum; a scatter of 16-byte splat records), cut
//     each tile's list into chunks of at most 8192 records, and let one
//     workgroup a chunk add them in shared memory, then add the tile's sums
//     to the buffer: a plain store where a tile has one chunk, a global atomic
//     a pixel where it has several. Chunks spread dense tiles over many
//     workgroups. Views beyond 4K (8192 tiles) take the atomic path.
//   atomic: one invocation a particle adds to the sums with global atomics
//     (six a pixel): simple, and 6x slower on an H200 at 10^7 particles.
// [gpu] splat = "atomic" picks the second (GpuTuning; benchmark and tests);
// splat_chunk and splat_list set the chunk size and the records the lists
// hold (tests make both small). The result
// matches blending "over" exactly in alpha and, where overlapping particles
// share a colour, in colour (tests/contexts/particle_splat_test.cpp states the
// image tolerance). Levels (render.splat_detail, splat_common.glsl): a splat
// at least twice the detail wide is drawn on a grid of half, a quarter or an
// eighth the resolution and upsampled by the resolve, so its cost stops
// growing with its size; a splat is at most 31 of its grid's pixels wide
// (248 view pixels on the coarsest). A splat record
// keeps its centre in 1/8 pixel from -64, so views are at most 8127 pixels
// wide (an 8K wall's 7680 fit).
//
// Motion blur either smears each splat along its path (render.blur = smear)
// or draws it still, sums the splats' motion a tile, and blurs the particle
// buffers along it (filter: ParticleMotionFilter).
//
// Shadows (the light in channel 0, the sums weighed by -ln(1 - alpha):
// splat_common.glsl) and motion blur (smeared footprints) cost the splat
// passes registers and work even when unused (1.4x on an H100), so each is
// compiled in only where asked for: one set of programs per combination,
// made when first needed.
//
// Expects the view and render blocks bound (bindings 1 and 2), and with
// shadows the shadow map (ShadowHandles); needs the GL context current.
#pragma once

#include <memory>

#include <optional>

#include <glm/glm.hpp>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/gl/timestamp_spans.h"
#include "contexts/particles/particle_backend.h"
#include "contexts/particles/particle_motion_filter.h"
#include "contexts/render/frame_blocks.h"
#include "core/config/gpu_tuning.h"
#include "core/util/faster_choice.h"

namespace sandstorm {

class ViewTargets;

// What splats show beyond the particles' colour (render.shadows,
// render.shutter > 0 by render.blur's smear or filter), and whether large
// ones go to coarser levels (render.splat_detail > 0).
struct SplatLook {
  enum class Blur { None, Smear, Filter };
  bool shadows = false;
  Blur blur = Blur::None;
  bool levels = false;
};

// The view a draw is for and the one drawn next from the same particles (a
// wall's second eye), or null: the first view's binning then also lists the
// particles that may show in the next one, whose binning visits only those
// (tiled variant). A CAVE's side walls and floor see a few percent of the
// particles, and their second eye no longer reads all of them. The next
// draw must describe `next` exactly (the same view block) and come before the
// particles change (ParticleSplat::particlesChanged), or it reads them all.
struct SplatViews {
  const View* view = nullptr;
  const View* next = nullptr;
};

class ParticleSplat {
 public:
  // `tuning`: tiled or atomic, the chunk and list sizes (GpuTuning).
  explicit ParticleSplat(const GpuTuning& tuning = {});
  // Replaces the view's particle buffers with the splatted particles. `sprite`:
  // ParticleRender's puff texture.
  void draw(const ParticleBackend& particles, const ViewTargets& targets, std::uint32_t sprite,
            SplatLook look = {}, SplatViews views = {}) const;
  // The particles moved (an update): a listed next view's list is stale.
  void particlesChanged() { nextListed_.reset(); }
  // A view that draws billboards: the trails (render.trail_length), by the
  // same passes, blended unlit over the view's scene colour, hidden behind
  // the scene as with splats. With the view and render blocks bound.
  void drawTrailsOverScene(const ParticleBackend& particles, const ViewTargets& targets) const;

 private:
  struct Programs {
    gl::Program splat, resolve;
    std::optional<gl::Program> bin, tile;  // tiled
    // Trails: the atomic variant and the tiled one's passes, made on first use.
    mutable std::unique_ptr<gl::Program> trails, trailBin, trailTile;
  };
  const Programs& programs(SplatLook look) const;
  static bool hasTrails(const ParticleBackend::Records& records);
  // The sums of `pixels` pixels, bound; the dispatch sizes from the live count.
  void bindSums(std::size_t pixels) const;
  // Motion blur's filter: the motion sums of `tiles` tiles (splat_common.glsl), bound.
  void bindMotionSums(std::size_t tiles) const;
  void prepare(const ParticleBackend::Records& records) const;
  // The tiled variant's bins and lists, bound.
  void bindTiles(std::size_t tileCount, std::size_t listCapacity) const;
  // The trails' pixels into their two sums, by the pass trailPass() picks.
  void addTrailSums(const ParticleBackend::Records& records, std::size_t capacity, glm::ivec2 size,
                    bool tiled) const;
  // Add every particle's footprint to the sums.
  void addAtomic(const Programs& p) const;
  void addTrails(const ParticleBackend::Records& records, std::size_t capacity) const;
  // The binning's list of the particles in view (splat_bin.comp), for up to
  // `particles`, bound.
  void bindInView(std::size_t particles) const;
  // What a view's binning does with the next view's list (splat_bin.comp's
  // uNextList): nothing, list the particles that may show in the view bound
  // as the next one, or visit only those the last view listed.
  enum class NextList : int { None = 0, List = 1, Visit = 2 };
  // `tileCount`: of every level's grid; `levels`: how many the view uses;
  // `listCapacity`: the splat records the lists hold (listRecords);
  // `particles`: the backend's capacity; `next`: as nextList() chose.
  void addTiled(const Programs& p, std::size_t tileCount, int levels, std::size_t listCapacity,
                std::size_t particles, NextList next) const;
  // This view's NextList, with the next view's block and the list bound.
  NextList nextList(const ParticleBackend::Records& records, SplatViews views, glm::ivec2 size,
                    std::size_t tileCount, std::size_t particles) const;
  // Trails in the tiled variant, after addTiled; `tileCount`: the full-resolution grid's.
  void addTiledTrails(const ParticleBackend::Records& records, std::size_t tileCount) const;
  // The splat records (16 bytes) the lists hold for `capacity` particles and
  // their trails of `trailLength` positions (0: none).
  std::size_t listRecords(std::size_t capacity, int trailLength) const;
  // Which trail pass a tiled view runs ([gpu] trail_pass; auto: trailChoice_).
  static constexpr int kAtomicTrails = 0, kTiledTrails = 1;
  FasterChoice::Run trailPass() const;

  bool tiled_;
  GpuTuning::TrailPass trailTuning_;
  // Auto: the faster trail pass, from timestamps of the passes as they run
  // (both add the same integers): three blocks of eight views each (all the
  // views a system draws a frame, bench included), kept for 4000 views.
  mutable FasterChoice trailChoice_{3, 8, 4000};
  mutable gl::TimestampSpans trailSpans_;
  std::uint32_t chunk_;             // tiled: list entries a workgroup
  std::size_t listRecords_;         // tiled: records the lists hold, 0: two a particle
  std::size_t maxListRecords_ = 0;  // what one storage buffer can hold
  gl::Program prepare_;
  gl::Program clear_;                // levels: zeroes the marked tiles' sums and the marks
  std::optional<gl::Program> scan_;  // tiled
  mutable std::unique_ptr<Programs> variants_[2][3];  // [shadows][SplatLook::Blur]
  // Motion blur by the filter, made on first use: the tiles' motion sums, the filter.
  mutable gl::Buffer motion_;
  mutable std::size_t motionTiles_ = 0;
  mutable std::unique_ptr<ParticleMotionFilter> filter_;
  gl::Buffer dispatch_, chunkDispatch_, nextViewBlock_;
  mutable gl::Buffer accumulation_;  // the sums
  mutable std::size_t pixels_ = 0;
  mutable gl::Buffer occupied_;  // the coarser levels' tiles with splats
  mutable std::size_t occupancy_ = 0;
  mutable gl::Buffer tileCounts_, tileStarts_, chunkStarts_, groupBase_,
      tileLists_;  // tiled: the bins
  mutable std::size_t tiles_ = 0, listCapacity_ = 0;
  // tiled: the particles each binning workgroup found in view, and how many.
  mutable gl::Buffer inView_, inViewCount_;
  mutable std::size_t inViewCapacity_ = 0;
  // tiled: the particles that may show in the next view (SplatViews), a
  // count a binning workgroup first; that view's block; and what the list
  // is for: the view it was made for and the particles it lists.
  struct NextListed {
    ViewBlock view;
    ParticleBackend::Records records;
  };
  mutable gl::Buffer nextInView_;
  mutable std::size_t nextInViewCapacity_ = 0;
  mutable std::optional<NextListed> nextListed_;
  // Trails, made on first use: the atomic variant's passes, the tiled one's.
  mutable std::unique_ptr<gl::Program> trailPrepare_, trails_, trailBin_, trailTile_,
      trailOverScene_;
  mutable gl::Buffer trailDispatch_;
  mutable gl::Buffer trailStaged_;  // tiled trails: runs between their walk and their lists
  mutable std::size_t trailStagedBytes_ = 0;
};

}  // namespace sandstorm
