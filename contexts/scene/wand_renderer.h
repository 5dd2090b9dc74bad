// WandRenderer: the tracked wand as every wall sees it: a thin beam from the
// wand along its ray, a marker where the ray meets something (the menu, an
// emitter's handle, the ground), and a handle on each emitter the wand can
// grab. The ray comes from the packet in room metres and is drawn in the
// world through the packet's navigation, so it lines up across the seams.
// Draws into the bound framebuffer with depth, using the view block already
// bound (binding 1), like the rest of the scene.
#pragma once

#include <vector>

#include "contexts/gl/program.h"
#include "contexts/scene/unit_cube.h"
#include "core/cave/viewer.h"
#include "core/sim/emitter.h"
#include "core/tracking/wand_ray.h"

namespace sandstorm {

class WandRenderer {
 public:
  static constexpr float kBeamWidth = 0.006f;  // m (room)
  static constexpr float kMarkerSize = 0.03f;  // m (room)
  static constexpr float kHandleSize = 0.06f;  // m (room)

  WandRenderer();
  // `handles`: what the wand can grab (core/tracking/wand_handles.h), world.
  void set(const WandRay& ray, const Navigation& navigation, std::vector<glm::vec3> handles);
  void draw() const;
  // Whether draw() draws anything (SceneRenderer::rasterItems).
  bool visible() const { return ray_.visible; }

 private:
  void box(const glm::mat4& model, const glm::vec3& color) const;

  gl::Program mesh_;
  UnitCube cube_;
  WandRay ray_;
  Navigation navigation_;
  std::vector<glm::vec3> handles_;  // world
};

}  // namespace sandstorm
