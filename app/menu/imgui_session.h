// ImGuiSession: a Dear ImGui context for the menu, on the main thread. Input
// comes from a GLFW window (the operator window, or the wall that shows the
// menu) or, with no window, from injected events (tests and scripted demos).
// Each frame: begin() ... widgets ... end() -> UiDrawData for a UiRenderer.
#pragma once

#include <memory>

#include <glm/glm.hpp>

#include "contexts/ui/ui_draw_data.h"
#include "core/config/app_config.h"

struct GLFWwindow;
struct ImGuiContext;

namespace sandstorm {

class ImGuiSession {
 public:
  // `window` may be null: then the display is `size` pixels and input is injected.
  // `eyes`: the window (or the `size` image) shows a stereo layout with an
  // image an eye (side by side, top-bottom); the menu is laid out for one
  // eye's image, drawn into each, and the mouse over either half points into it.
  ImGuiSession(GLFWwindow* window, glm::ivec2 size, StereoMode eyes = StereoMode::Mono);
  ~ImGuiSession();
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;

  void begin(float dt);
  std::shared_ptr<const UiDrawData> end();
  const UiFont& font() const { return font_; }

  // Injected input for this frame (overrides the window's).
  void injectMouse(glm::vec2 position, bool down);
  // Draw ImGui's own cursor into the menu (a wand on a wall has no system cursor).
  void drawCursor(bool on);
  bool wantsMouse() const;
  bool wantsKeyboard() const;

 private:
  ImGuiContext* context_ = nullptr;
  ImGuiContext* previous_ = nullptr;  // current before begin(); current again after end()
  GLFWwindow* window_;
  glm::ivec2 size_;
  StereoMode eyes_;
  UiFont font_;
  bool injected_ = false;
  glm::vec2 mouse_{0.0f};
  bool mouseDown_ = false;
};

}  // namespace sandstorm
