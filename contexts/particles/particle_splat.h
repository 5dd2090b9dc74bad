// ParticleSplat: a compute-shader renderer for small particles (issue 6): it
// writes the same particle buffers ParticleRender's billboards write (the
// premultiplied colour and normal that ParticlePost lights), without the
// raster pipeline, which on datacenter GPUs tops out far below their compute.
//
// Three passes (shaders/splat_*.comp, particle_splat*.comp): size the splat
// pass from the backend's GPU-side count; one invocation per particle adds its
// billboard's footprint (same size, sprite, normal, colour, soft depth test
// against the scene) to order-independent fixed-point sums per pixel; the
// resolve turns the sums into the particle buffers and zeroes them. The result
// matches blending "over" exactly in alpha and, where overlapping particles
// share a colour, in colour (tests/contexts/particle_splat_test.cpp states the
// image tolerance). Particles wider than 32 pixels are drawn 32 pixels wide:
// render.mode = auto leaves large particles to billboards.
//
// Expects the view and render blocks bound (bindings 1 and 2); needs the GL
// context current.
#pragma once

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
  void draw(const ParticleBackend& particles, const ViewTargets& targets, std::uint32_t sprite) const;

 private:
  gl::Program prepare_, splat_, resolve_;
  gl::Buffer dispatch_;
  mutable gl::Buffer accumulation_;
  mutable std::size_t pixels_ = 0;
};

}  // namespace sandstorm
