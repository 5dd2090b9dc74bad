// ParticlePost: deferred particle shading (thesis 5.1.3). Lights the
// accumulated particles once per pixel with their accumulated normals and the
// light direction, and composites them over the scene's colour into the
// destination framebuffer's viewport: by compute where the destination's
// colour is an RGBA8 texture (offscreen walls: the raster pipeline of a
// datacenter GPU fills pixels slowly), else by a full-screen triangle.
// Expects the view and render blocks bound (bindings 1 and 2).
#pragma once

#include <glm/glm.hpp>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"

namespace sandstorm {

class ViewTargets;

class ParticlePost {
 public:
  ParticlePost();
  // Writes the view's image at `origin` (pixels) of the bound destination
  // framebuffer `destination`.
  void draw(const ViewTargets& targets, std::uint32_t destination, glm::ivec2 origin) const;
  // Whether draw() composites into `destination` by compute (its colour is
  // an RGBA8 texture) rather than by raster.
  static bool computes(std::uint32_t destination);

 private:
  gl::Program composite_, computeComposite_;
  gl::VertexArray emptyVao_;
};

}  // namespace sandstorm
