// ViewRenderer: one image of the room for one eye: the scene into offscreen
// buffers (raster items, then the ground and sky by compute, then the
// translucent items), then the particle system's render and post passes on top, into a
// region of the destination framebuffer (the whole of it, or one half for
// side-by-side stereo).
#pragma once

#include <memory>
#include <optional>

#include "contexts/gl/frame_stage_timer.h"
#include "contexts/gl/objects.h"
#include "contexts/render/view_targets.h"
#include "contexts/scene/scene_background.h"
#include "contexts/scene/scene_renderer.h"
#include "core/cave/view.h"
#include "core/color/color_map.h"

namespace sandstorm {

class ParticleSystem;

class ViewRenderer {
 public:
  ViewRenderer();

  SceneRenderer& scene() { return scene_; }
  // `timer` (may be null) measures the scene, particle and post stages.
  // `next`: the view drawn next from the same particles (a wall's second
  // eye), or null; its splats' binning then reads fewer (SplatViews).
  void render(const ParticleSystem& particles, const View& view, glm::ivec2 size,
              std::uint32_t destination, glm::ivec2 origin, gl::FrameStageTimer* timer = nullptr,
              const View* next = nullptr);
  // render()'s first half, for callers that time the stages apart
  // (sandstorm-bench): binds the view and render blocks and draws the scene
  // into targets(); the particle system's passes follow.
  void drawScene(const ParticleSystem& particles, const View& view, glm::ivec2 size);
  const ViewTargets& targets() const { return targets_; }

 private:
  SceneRenderer scene_;
  SceneBackground background_;
  ViewTargets targets_;
  gl::Buffer viewBlock_, renderBlock_;
  ColorTableCache colorTables_;
};

}  // namespace sandstorm
