// TrailRenderer: draws the particles' trails (ParticleBackend::Records'
// trail ring, render.trail_length) as lines into the scene, each in its
// particle's colour, fading from the particle's opacity to nothing at the
// trail's end, depth-tested against the scene without writing depth. Works
// from the records alone, so a shared simulation's readers draw the owner's
// trails. Needs its GL context current.
#pragma once

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/particles/particle_backend.h"

namespace sandstorm {

class TrailRenderer {
 public:
  TrailRenderer();
  // With the view and render blocks bound, into the bound framebuffer.
  void draw(const ParticleBackend::Records& records, std::size_t capacity) const;

 private:
  gl::Program program_, command_;
  gl::VertexArray emptyVao_;
  gl::Buffer commandBuffer_;  // the draw command, made from the live count
};

}  // namespace sandstorm
