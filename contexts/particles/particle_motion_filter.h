// ParticleMotionFilter: motion blur for splats (render.shutter with
// render.blur = filter) as a gather over the particle buffers rather than a
// smear of every splat: the splats are drawn still, the splat passes sum
// their motion over the shutter a tile (splat_common.glsl), and three passes
// turn those sums into a motion field of 8-pixel cells, find how far motion
// reaches each 16-pixel tile, and blur the premultiplied buffers along each
// pixel's motion (shaders/particle_motion_filter.comp says how). Its cost
// is a pass over the view's pixels, not the extra pixels each smear covers
// (with 10^7 particles a smear covered several times its still footprint).
//
// ParticleSplat's resolve writes into the filter's own buffers
// (bindResolveImages), then apply() blurs them into the view's particle
// buffers. Needs the GL context current.
#pragma once

#include <glm/glm.hpp>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"

namespace sandstorm {

class ViewTargets;

class ParticleMotionFilter {
 public:
  ParticleMotionFilter();
  // Binds image units 0-2 to the unblurred colour, normal and light, sized
  // to the view, for the resolve to write.
  void bindResolveImages(glm::ivec2 size) const;
  // Blurs them into the view's particle buffers along the motion the splat
  // passes summed a tile (splat_common.glsl; the sums bound at binding 16,
  // the view block at 1) over `levels` levels. `shadows`: the light buffer
  // is its own (render.shadows), else the opacity.
  void apply(const ViewTargets& targets, int levels, bool shadows) const;

 private:
  void resize(glm::ivec2 size) const;

  gl::Program field_, reach_, filter_, shadowedFilter_;
  mutable glm::ivec2 size_{0};
  // The resolve's images; the motion field's means a cell of 8x8 pixels;
  // each 16-pixel tile's longest motion axis reaching it.
  mutable gl::Texture color_, normal_, light_, cells_, reachTexture_;
};

}  // namespace sandstorm
