// SceneBackground: a view's flat ground and sky, by a compute pass after the
// raster scene items (scene_background.comp), and the scene's depth that the
// particle passes test against. On datacenter GPUs the raster pipeline fills
// pixels slowly: the flat ground and sky as raster took 0.2-0.3 ms of a
// 1920x1080 view on an H100, most of a view's scene stage. A height map's
// terrain stays raster (SceneRenderer); the pass then adds the sky only.
//
// Expects the view and render blocks (bindings 1 and 2) and the shadow block
// bound; needs the GL context current.
#pragma once

#include <optional>
#include <span>

#include <glm/glm.hpp>

#include "contexts/gl/program.h"
#include "core/cave/window_segments.h"

namespace sandstorm {

class ViewTargets;

// A flat ground: its extent in x and y and its height (SceneRenderer finds it
// once, when the terrain is set).
struct FlatGround {
  glm::vec2 min, max;
  float height = 0.0f;
};

class SceneBackground {
 public:
  SceneBackground();
  // Fills the pixels of `targets`' scene colour that no raster item covers
  // nearer than the ground (or at all, for the sky), and writes its scene
  // depth. `ground`: the scene's ground where flat (none: a height map's,
  // drawn by raster, or no ground). `items`: whether raster items were drawn
  // into the targets' items depth (else it is not read: nothing lies in front).
  // `lines` (at most kMaxLines, the field box's edges in window space): opaque
  // one-pixel lines of `lineColor`, drawn as GL rasterises lines (a pixel a
  // column for a mostly horizontal line, a row for a mostly vertical one),
  // depth-tested against the items and the ground.
  void draw(const ViewTargets& targets, const std::optional<FlatGround>& ground, bool items,
            std::span<const WindowSegment> lines = {}, glm::vec3 lineColor = glm::vec3(0.0f)) const;

  static constexpr int kMaxLines = 12;

 private:
  gl::Program program_;
};

}  // namespace sandstorm
