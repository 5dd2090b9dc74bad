// ParticleRender: draws the update's particles into a view's particle buffer
// (thesis 5.1.3): spherical billboards facing the eye, textured with a soft
// puff, blended premultiplied (ONE, ONE_MINUS_SRC_ALPHA), with their sphere
// normals accumulated alongside for ParticlePost; or opaque points. Particles
// test themselves against the scene's depth and fade out near it.
#pragma once

#include <memory>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "core/sim/sim_settings.h"

namespace sandstorm {

class ParticleBackend;
class ParticleSort;
class ViewTargets;

class ParticleRender {
 public:
  ParticleRender();
  ~ParticleRender();
  // Expects the view and render blocks bound (bindings 1 and 2). `order`:
  // billboards sorted back to front first (ParticleSort), from the records
  // and the live count the backend keeps on the GPU (both backends do).
  void draw(const ParticleBackend& particles, const ViewTargets& targets, RenderMode mode,
            RenderOrder order = RenderOrder::Unsorted) const;
  // The soft puff billboards are textured with (ParticleSplat draws with it too).
  std::uint32_t sprite() const { return sprite_.id(); }

 private:
  gl::Program billboards_, points_;
  gl::Texture sprite_;
  // render.order = sorted: made when first asked for.
  mutable std::unique_ptr<gl::Program> sortedBillboards_;
  mutable std::unique_ptr<ParticleSort> sort_;
  gl::VertexArray empty_;
};

}  // namespace sandstorm
