// WindowSegments: straight edges of the world (a field's box) as a view's
// window shows them, for a compute pass to draw as one-pixel lines where the
// raster pipeline would have (a raster pass cost 0.3 ms a CAVE wall on an
// H100 however little it drew: SceneBackground draws the box instead).
//
// Each segment is clipped to the view's near and far planes in clip space
// (a viewer standing inside the box sees the edges that pass beside and
// behind the eye up to the near plane), then projected: x and y in window
// pixels (the viewport's lower-left corner at 0, pixel centres at +0.5, as
// gl_FragCoord), z the window depth in 0..1, which is affine along the
// segment on the screen.
#pragma once

#include <array>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace sandstorm {

struct WindowSegment {
  glm::vec3 a{0.0f}, b{0.0f};
};

std::vector<WindowSegment> windowSegments(const glm::mat4& viewProjection, glm::vec2 size,
                                          std::span<const std::array<glm::vec3, 2>> world);

// The twelve edges of the unit cube [0,1]^3 carried by `model`.
std::array<std::array<glm::vec3, 2>, 12> boxEdges(const glm::mat4& model);

}  // namespace sandstorm
