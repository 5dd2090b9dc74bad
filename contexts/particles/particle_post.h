// ParticlePost: deferred particle shading (thesis 5.1.3). Lights the
// accumulated particles once per pixel with their accumulated normals and the
// light direction, and composites them over the scene's colour into the
// destination framebuffer's viewport. Expects the render block bound (binding 2).
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

 private:
  gl::Program composite_;
  gl::VertexArray emptyVao_;
};

}  // namespace sandstorm
