// MoleculeRenderer: draws a frame's molecules (MoleculeHandles: a wall's own
// MoleculeUpdate's, or those a shared simulation's owner published) into a
// view's particle buffers after the particles (the same blending, ONE,
// ONE_MINUS_SRC_ALPHA, and the same colour, opacity and soft-depth rules), so
// ParticlePost's deferred pass lights both: faces for solid shapes,
// eye-facing tube-shaded ribbons for rods and chains
// (shaders/molecule_render.*). One instanced, indirect draw: nothing is read
// back. Expects the view, render and shadow blocks bound.
#pragma once

#include <vector>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/molecules/molecule_handles.h"
#include "core/sim/particle.h"

namespace sandstorm {

class ViewTargets;

class MoleculeRenderer {
 public:
  MoleculeRenderer();
  void draw(const MoleculeHandles& molecules, const ViewTargets& targets) const;

 private:
  gl::Program program_;
  gl::VertexArray empty_;
};

// The molecules' members' records, molecule after molecule (member j of
// molecule i at i * members + j, as MoleculeReference keeps them), through staging copies in the
// calling context (its buffers may be another context's). Waits for the GPU: tests and dumps, not
// the frame loop.
std::vector<Particle> readMolecules(const MoleculeHandles& molecules);

}  // namespace sandstorm
