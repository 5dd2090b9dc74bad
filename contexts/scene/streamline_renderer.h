// StreamlineRenderer: the streamlines of the rake (ParticleState::streamlines)
// through this wall's field, traced on the GPU (shaders/streamline_trace.comp,
// the twin of core/flow's traceStreamlines) whenever the field, its blend, the
// rake, the integrator or the field strength changes, and drawn into the scene
// as ribbons (streamlines.width metres) or one-pixel lines, coloured like the
// particles (render.color_by, render.color_map).
//
// It reads the scene's copy of the field (SceneField). Needs its GL context
// current for every call.
#pragma once

#include <memory>
#include <optional>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/scene/scene_field.h"
#include "contexts/scene/scene_field_program.h"
#include "core/flow/streamline_tracer.h"
#include "core/sim/frame_packet.h"

namespace sandstorm {

class StreamlineRenderer {
 public:
  explicit StreamlineRenderer(SceneField& field);

  // Once a frame, before the views are drawn, after `field` has this frame's field.
  void update(const ParticleState& state, std::shared_ptr<const FieldUpdate> field, float blend);
  // Into the bound framebuffer, with the view and render blocks bound.
  void draw() const;
  // Whether draw() draws anything (SceneRenderer::rasterItems).
  bool visible() const { return enabled_ && lineCount_ > 0 && steps_ > 0; }
  // The lines last traced, read back (tests); empty while streamlines are off.
  std::vector<Streamline> readBack() const;

 private:
  struct Key {
    const VectorField* field = nullptr;
    const VectorField* next = nullptr;
    float blend = 0.0f;
    FieldPlacement placement;
    StreamlineSettings rake;
    float strength = 1.0f;
    std::vector<Obstacle> obstacles;
    bool operator==(const Key& o) const;
  };
  void trace(const ParticleState& state);

  SceneFieldProgram trace_;
  gl::Program ribbons_, lines_;
  gl::VertexArray emptyVao_;
  SceneField& field_;
  gl::Buffer seeds_, points_, counts_;
  std::optional<Key> traced_;
  bool enabled_ = false;
  float width_ = 0.0f;
  int lineCount_ = 0, steps_ = 0;  // as traced: two lines a seed, steps_ + 1 points a line
  std::size_t pointCapacity_ = 0, seedCapacity_ = 0, countCapacity_ = 0;
};

}  // namespace sandstorm
