// SliceRenderer: the slice plane (ParticleState::slice) where it cuts the
// field's box (core/flow/slice_polygon), each pixel coloured by the field
// there (the scene's copy of the field, SceneField) through the particles'
// colour quantity and map. Opaque slices write depth, so particles behind
// them are hidden and those in front fade into them like into the ground.
// With slice.arrows, arrow glyphs of the in-plane flow (core/flow/slice_arrows)
// are drawn on it as dark lines, made on the CPU from the field each frame.
#pragma once

#include <memory>
#include <vector>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/scene/scene_field.h"
#include "contexts/scene/scene_field_program.h"

namespace sandstorm {

class SliceRenderer {
 public:
  explicit SliceRenderer(SceneField& field);

  // Once a frame, after `field` has this frame's field.
  void update(const ParticleState& state, const std::shared_ptr<const FieldUpdate>& field,
              float blend);
  // Into the bound framebuffer, with the view and render blocks bound.
  void draw() const;
  // Whether draw() draws anything (SceneRenderer::rasterItems).
  bool visible() const { return polygon_.size() >= 3 && field_.has(); }

 private:
  SceneField& field_;
  SceneFieldProgram program_;
  gl::Program arrowProgram_;
  gl::VertexArray emptyVao_, arrowVao_;
  gl::Buffer arrowLines_;
  std::size_t arrowCapacity_ = 0;  // points the buffer holds
  int arrowPoints_ = 0;            // points of the lines to draw
  // What the arrows were made from (the field's update, its blend, the plane,
  // the grid and the strength): equal, they need not be made again.
  struct ArrowsOf {
    std::shared_ptr<const FieldUpdate> field;
    float blend = 0.0f;
    glm::vec3 origin{0.0f}, normal{0.0f};
    int arrows = 0;
    float strength = 0.0f;
    std::vector<Obstacle> obstacles;
    bool operator==(const ArrowsOf&) const = default;
  };
  ArrowsOf arrowsOf_;
  std::vector<glm::vec3> polygon_;
  ParticleState state_;
};

}  // namespace sandstorm
