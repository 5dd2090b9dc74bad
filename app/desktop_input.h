// DesktopInput: the desktop simulator's controls, read on the main thread from
// the windows: W/S/A/D or the arrow keys walk the head (Q/E turn it, R/F raise
// and lower it); dragging with the left mouse button turns the world about the
// room's vertical axis, the scroll wheel scales it. Ignored while the menu has
// the mouse or keyboard. Make it before the menu's ImGuiSession, so ImGui's
// GLFW callbacks chain to its own.
#pragma once

#include <vector>

#include "core/cave/viewer.h"

struct GLFWwindow;

namespace sandstorm {

class DesktopInput {
 public:
  explicit DesktopInput(std::vector<GLFWwindow*> windows);
  ~DesktopInput();
  // `head` may be null (a fixed or scripted head is not moved by keys).
  void update(float dt, DesktopHead* head, Navigation& navigation, bool menuHasMouse,
              bool menuHasKeyboard);

 private:
  std::vector<GLFWwindow*> windows_;
  bool dragging_ = false;
  double lastX_ = 0.0;
};

}  // namespace sandstorm
