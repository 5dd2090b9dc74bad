// UiRenderer: draws UiDrawData (the menu) over the bound framebuffer, alpha
// blended and scissored per command, as Dear ImGui's OpenGL backend does, but
// on whichever thread and context shows the menu.
#pragma once

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/ui/ui_draw_data.h"

namespace sandstorm {

class UiRenderer {
 public:
  explicit UiRenderer(const UiFont& font);
  // Over whatever the bound framebuffer holds.
  void draw(const UiDrawData& data, glm::ivec2 framebufferSize) {
    draw(data, glm::ivec4(0, 0, framebufferSize));
  }
  // Into `viewport` (x, y, width, height, y up) of the bound framebuffer: an
  // eye's half of a stereo image.
  void draw(const UiDrawData& data, glm::ivec4 viewport);
  // The whole default framebuffer: cleared to a backdrop, then the menu (an operator window).
  void drawWindow(const UiDrawData& data, glm::ivec2 framebufferSize);

 private:
  gl::Program program_;
  gl::Texture font_;
  gl::VertexArray vao_;
  gl::Buffer vertices_, indices_;
  std::size_t vertexCapacity_ = 0, indexCapacity_ = 0;
};

}  // namespace sandstorm
