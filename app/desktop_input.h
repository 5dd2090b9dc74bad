// DesktopInput: the desktop simulator's controls, read on the main thread from
// the windows: W/S/A/D or the arrow keys walk the head (Q/E turn it, R/F raise
// and lower it); dragging with the left mouse button turns the world about the
// room's vertical axis, unless the press picked an object (setPicker: an
// obstacle, dragged along the floor, takeDrag); the scroll wheel scales the
// world; a right click is kept for the probe (takeClick). Ignored while the menu has the mouse or
// keyboard. Make it before the menu's ImGuiSession, so ImGui's GLFW callbacks chain to its own.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

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

  // The last right click since the previous call: the window (an index into
  // the constructor's list) and where, in [0, 1]^2 of the window, y down.
  struct Click {
    std::size_t window = 0;
    glm::vec2 at{0.0f};
  };
  std::optional<Click> takeClick();

  // Asked at each left press: true when the press grabbed an object, whose
  // drag then follows the cursor instead of turning the world.
  using Picker = std::function<bool(const Click&)>;
  void setPicker(Picker picker) { picker_ = std::move(picker); }
  // While an object is held: where the cursor is now; `released` on the
  // frame the button comes up.
  struct Drag {
    Click at;
    bool released = false;
  };
  std::optional<Drag> takeDrag();

 private:
  std::vector<GLFWwindow*> windows_;
  bool dragging_ = false;
  bool holding_ = false;  // the left drag moves a picked object
  Picker picker_;
  std::optional<Drag> drag_;
  double lastX_ = 0.0;
  bool rightDown_ = false;
  std::optional<Click> click_;
};

}  // namespace sandstorm
