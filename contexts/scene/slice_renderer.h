// SliceRenderer: the slice plane (ParticleState::slice) where it cuts the
// field's box (core/flow/slice_polygon), each pixel coloured by the field
// there (the scene's copy of the field, SceneField) through the particles'
// colour quantity and map. Opaque slices write depth, so particles behind
// them are hidden and those in front fade into them like into the ground.
#pragma once

#include <vector>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/scene/scene_field.h"

namespace sandstorm {

class SliceRenderer {
 public:
  explicit SliceRenderer(SceneField& field);

  // Once a frame, after `field` has this frame's field.
  void update(const ParticleState& state, const FieldUpdate* field);
  // Into the bound framebuffer, with the view and render blocks bound.
  void draw() const;

 private:
  SceneField& field_;
  gl::Program program_;
  gl::VertexArray emptyVao_;
  std::vector<glm::vec3> polygon_;
  ParticleState state_;
};

}  // namespace sandstorm
