// ParticleRender: draws the update's particles into a view's particle buffer
// (thesis 5.1.3): spherical billboards facing the eye, textured with a soft
// puff, blended premultiplied (ONE, ONE_MINUS_SRC_ALPHA), with their sphere
// normals accumulated alongside for ParticlePost; or opaque points. Particles
// test themselves against the scene's depth and fade out near it.
#pragma once

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "core/sim/sim_settings.h"

namespace sandstorm {

class ParticleBackend;
class ViewTargets;

class ParticleRender {
 public:
  ParticleRender();
  // Expects the view and render blocks bound (bindings 1 and 2).
  void draw(const ParticleBackend& particles, const ViewTargets& targets, RenderMode mode) const;
  // The soft puff billboards are textured with (ParticleSplat draws with it too).
  std::uint32_t sprite() const { return sprite_.id(); }

 private:
  gl::Program billboards_, points_;
  gl::Texture sprite_;
};

}  // namespace sandstorm
