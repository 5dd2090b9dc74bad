// MoleculeRenderer: draws a MoleculeUpdate's molecules into a view's particle
// buffers after the particles (the same blending, ONE, ONE_MINUS_SRC_ALPHA,
// and the same colour, opacity and soft-depth rules), so ParticlePost's
// deferred pass lights both: faces for solid shapes, eye-facing tube-shaded
// ribbons for rods and chains (shaders/molecule_render.*). One instanced,
// indirect draw: nothing is read back. Expects the view, render and shadow
// blocks bound and the molecule block as the update left it (binding 5).
#pragma once

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/molecules/molecule_update.h"

namespace sandstorm {

class ViewTargets;

class MoleculeRenderer {
 public:
  MoleculeRenderer();
  void draw(const MoleculeUpdate& molecules, std::uint32_t moleculeBlock,
            const ViewTargets& targets) const;

 private:
  gl::Program program_;
  gl::VertexArray empty_;
};

}  // namespace sandstorm
