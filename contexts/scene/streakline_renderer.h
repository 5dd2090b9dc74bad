// StreaklineRenderer: the point emitters' streaklines (render.streaklines) on
// this wall's GPU: a ring of render.streak_length points per emitter, moved
// each frame by shaders/streak_update.comp as StreaklineReference (the CPU
// twin, core/flow/streaklines.h) moves them, and drawn as lines coloured like
// the particles (the colour map's age is the point's place along the line).
// Reads the scene's copy of the field (SceneField). Needs its GL context current.
#pragma once

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/scene/scene_field.h"
#include "contexts/scene/scene_field_program.h"
#include "core/flow/streaklines.h"

namespace sandstorm {

class StreaklineRenderer {
 public:
  explicit StreaklineRenderer(SceneField& field);

  // Once a frame, after `field` has this frame's field and step (dt > 0).
  void update(const ParticleState& state, float dt, bool reset);
  void draw() const;
  // Whether draw() draws anything (SceneRenderer::rasterItems).
  bool visible() const { return enabled_ && length_ >= 2; }
  // Emitter e's points, newest first, the valid ones (tests).
  std::vector<StreakPoint> readBack(int emitter) const;

 private:
  SceneField& field_;
  SceneFieldProgram update_;
  gl::Program draw_;
  gl::VertexArray emptyVao_;
  gl::Buffer ring_;
  int length_ = 0, head_ = 0;
  bool enabled_ = false;
};

}  // namespace sandstorm
