// MenuHost: runs the menu on the main thread each frame and puts it where it
// is shown: its own operator window (drawn here), or over one wall (handed to
// that wall's thread as UiDrawData). Never on every wall.
#pragma once

#include <memory>
#include <mutex>
#include <optional>

#include "app/menu/imgui_session.h"
#include "app/menu/menu_panel.h"
#include "app/menu/menu_script.h"
#include "contexts/platform/glfw_window.h"
#include "contexts/ui/ui_renderer.h"

namespace sandstorm {

class MenuHost {
 public:
  // With `operatorWindow` the menu is drawn there; otherwise over a wall, whose
  // window (`wallWindow`, may be null when offscreen) gives the input. On a
  // wall with an image an eye (`wallStereo` side by side or top-bottom) it is
  // laid out for one eye's image, to be drawn into each (a menu in one eye
  // only cannot be read), and the wand's and the mouse's pixels are that image's.
  MenuHost(MainContext& main, std::unique_ptr<GlfwWindow> operatorWindow, GLFWwindow* wallWindow,
           glm::ivec2 wallSize, StereoMode wallStereo, std::vector<std::string> fieldChoices,
           MenuPanel::FieldLoader loader, MenuPanel::FieldWriter writer,
           std::optional<MenuScript> script);
  ~MenuHost();

  void frame(std::uint32_t frame, float dt, const MenuStats& stats);
  // The tracked wand points at the panel this frame: its hit in the wall
  // image's pixels, and whether the trigger is down (a mouse of its own).
  void pointWand(glm::vec2 pixel, bool down);
  MenuPanel::Rect panelRect() const { return panel_.panelRect(); }

  // For the wall that shows the menu.
  std::shared_ptr<const UiDrawData> latest() const;
  const UiFont& font() const { return session_.font(); }
  bool wantsMouse() const { return session_.wantsMouse(); }
  bool operatorWindowClosed() const;
  // The menu script asked for the windows to close (tests of closing a window).
  bool scriptCloses(std::uint32_t frame) const { return script_ && script_->closesBy(frame); }

 private:
  std::unique_ptr<GlfwWindow> operatorWindow_;
  ImGuiSession session_;
  MenuPanel panel_;
  std::optional<MenuScript> script_;
  std::optional<std::pair<glm::vec2, bool>> wand_;  // this frame's wand pointer
  bool wandPointed_ = false;                        // the wand drove the mouse last frame
  std::unique_ptr<UiRenderer> renderer_;            // operator window only, on this thread
  mutable std::mutex mutex_;
  std::shared_ptr<const UiDrawData> latest_;
};

}  // namespace sandstorm
