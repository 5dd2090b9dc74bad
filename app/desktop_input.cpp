#include "app/desktop_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <utility>

#include "core/util/log.h"

namespace sandstorm {
namespace {

std::atomic<double> scrolled{0.0};

void onScroll(GLFWwindow*, double, double dy) {
  scrolled = scrolled + dy;
}

}  // namespace

DesktopInput::DesktopInput(std::vector<GLFWwindow*> windows) : windows_(std::move(windows)) {
  // Made before the menu's ImGui session, whose GLFW backend then chains to these.
  for (GLFWwindow* w : windows_) {
    glfwSetScrollCallback(w, onScroll);
    // A click shorter than a frame still reads as pressed at the next poll.
    glfwSetInputMode(w, GLFW_STICKY_MOUSE_BUTTONS, GLFW_TRUE);
  }
}

DesktopInput::~DesktopInput() = default;

void DesktopInput::update(float dt, DesktopHead* head, Navigation& navigation, bool menuHasMouse,
                          bool menuHasKeyboard) {
  GLFWwindow* focused = nullptr;
  for (GLFWwindow* w : windows_)
    if (glfwGetWindowAttrib(w, GLFW_FOCUSED)) focused = w;
  if (!focused) return;
  if (head && !menuHasKeyboard) {
    const auto down = [&](int a, int b) {
      return glfwGetKey(focused, a) == GLFW_PRESS || glfwGetKey(focused, b) == GLFW_PRESS;
    };
    const float step = 1.5f * dt, turn = 1.2f * dt;
    head->move((down(GLFW_KEY_W, GLFW_KEY_UP) ? step : 0.0f) -
                   (down(GLFW_KEY_S, GLFW_KEY_DOWN) ? step : 0.0f),
               (down(GLFW_KEY_D, GLFW_KEY_RIGHT) ? step : 0.0f) -
                   (down(GLFW_KEY_A, GLFW_KEY_LEFT) ? step : 0.0f),
               (down(GLFW_KEY_R, GLFW_KEY_R) ? step : 0.0f) -
                   (down(GLFW_KEY_F, GLFW_KEY_F) ? step : 0.0f));
    head->turn((down(GLFW_KEY_Q, GLFW_KEY_Q) ? turn : 0.0f) -
               (down(GLFW_KEY_E, GLFW_KEY_E) ? turn : 0.0f));
  }
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(focused, &x, &y);
  const bool pressed = glfwGetMouseButton(focused, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  int width = 0, height = 0;
  glfwGetWindowSize(focused, &width, &height);
  const std::size_t index =
      std::size_t(std::find(windows_.begin(), windows_.end(), focused) - windows_.begin());
  const Click cursor{index,
                     glm::vec2(float(x / std::max(width, 1)), float(y / std::max(height, 1)))};
  if (pressed && !menuHasMouse) {
    if (!dragging_ && !holding_ && picker_ && width > 0 && height > 0) holding_ = picker_(cursor);
    if (holding_)
      drag_ = Drag{cursor, false};
    else if (dragging_)
      navigation.yawRadians += float(x - lastX_) * 0.005f;
    dragging_ = true;
  } else {
    if (holding_) drag_ = Drag{cursor, true};
    dragging_ = holding_ = false;
  }
  lastX_ = x;
  const bool right = glfwGetMouseButton(focused, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  if (right && !rightDown_) log::debug("right click (the menu has the mouse: ", menuHasMouse, ")");
  if (right && !rightDown_ && !menuHasMouse && width > 0 && height > 0) click_ = cursor;
  rightDown_ = right;
  const double wheel = scrolled.exchange(0.0);
  if (wheel != 0.0 && !menuHasMouse)
    navigation.scale = std::clamp(navigation.scale * float(std::pow(1.1, wheel)), 0.01f, 100.0f);
}

std::optional<DesktopInput::Drag> DesktopInput::takeDrag() {
  return std::exchange(drag_, std::nullopt);
}

std::optional<DesktopInput::Click> DesktopInput::takeClick() {
  return std::exchange(click_, std::nullopt);
}

}  // namespace sandstorm
