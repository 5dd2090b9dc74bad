// ParticleSplat: a compute-shader renderer for small particles (issue 6): it
// writes the same particle buffers ParticleRender's billboards write (the
// premultiplied colour and normal that ParticlePost lights), without the
// raster pipeline, which on datacenter GPUs tops out far below their compute.
//
// Each particle adds its billboard's footprint (same size, sprite, normal,
// colour, soft depth test against the scene: shaders/splat_footprint.glsl) to
// order-independent fixed-point sums per pixel, which a resolve turns into the
// particle buffers. Two variants add the same integers, so give the same image:
//   atomic (the default): one invocation a particle adds to a buffer of sums
//     with global atomics (six a pixel), then a resolve pass;
//   tiled: bin the particles by 16x16-pixel tile (count, prefix sum, scatter
//     of indices), then one workgroup a tile adds its particles in shared
//     memory and resolves its pixels: a few global atomics a particle, but on
//     an H200 2.4x slower than atomic at 10^7 particles, because the dense
//     tiles of a particle cloud leave a few workgroups most of the work.
// SANDSTORM_SPLAT=tiled picks the second (for the benchmark). The result
// matches blending "over" exactly in alpha and, where overlapping particles
// share a colour, in colour (tests/contexts/particle_splat_test.cpp states the
// image tolerance). Particles wider than 32 pixels are drawn 32 pixels wide:
// render.mode = auto leaves large particles to billboards.
//
// Expects the view and render blocks bound (bindings 1 and 2); needs the GL
// context current.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"

namespace sandstorm {

class ParticleBackend;
class ViewTargets;

class ParticleSplat {
 public:
  ParticleSplat();
  // Replaces the view's particle buffers with the splatted particles. `sprite`:
  // ParticleRender's puff texture.
  void draw(const ParticleBackend& particles, const ViewTargets& targets,
            std::uint32_t sprite) const;

 private:
  void drawAtomic(const ViewTargets& targets) const;
  void drawTiled(const ViewTargets& targets, std::size_t capacity) const;

  bool tiled_;
  gl::Program prepare_;
  std::optional<gl::Program> splat_, resolve_;                // atomic
  std::optional<gl::Program> count_, scatter_, scan_, tile_;  // tiled
  gl::Buffer dispatch_;
  mutable gl::Buffer accumulation_;  // atomic: the sums
  mutable std::size_t pixels_ = 0;
  mutable gl::Buffer tileCounts_, tileStarts_, tileLists_;  // tiled: the bins
  mutable std::size_t tiles_ = 0, listCapacity_ = 0;
};

}  // namespace sandstorm
