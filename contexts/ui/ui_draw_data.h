// UiDrawData: one frame of the menu, as triangles to draw: a copy of Dear
// ImGui's draw lists made on the main thread, so the thread of whichever
// context shows the menu (the operator window, or one wall) can draw it while
// the main thread builds the next frame. Holds no ImGui types.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace sandstorm {

struct UiVertex {  // the layout of ImDrawVert
  glm::vec2 position;
  glm::vec2 uv;
  std::uint32_t color;  // RGBA8
};

struct UiCommand {
  glm::vec4 clip;  // x0, y0, x1, y1 in display pixels
  std::uint32_t indexCount = 0;
  std::uint32_t firstIndex = 0;
  std::int32_t vertexOffset = 0;
};

struct UiDrawData {
  glm::vec2 displayPos{0.0f};
  glm::vec2 displaySize{0.0f};
  glm::vec2 framebufferScale{1.0f};
  std::vector<UiVertex> vertices;
  std::vector<std::uint16_t> indices;
  std::vector<UiCommand> commands;
};

// The font atlas, uploaded once per context that shows the menu.
struct UiFont {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
};

}  // namespace sandstorm
