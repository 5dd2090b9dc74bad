// MenuScript: scripted mouse input for the menu, for tests and unattended
// demos. Each action aims at a widget the panel drew (by attribute key, or
// "button:pause" and the like) and goes through Dear ImGui's own input, so the
// change takes the same path as a hand on the mouse:
//
//   # frame  action  widget          where across it (0..1, default 0.5)
//   30       click   render.size     0.8
//   60       click   button:pause
//   90       close                        (as if the user closed a window)
//
// A click hovers at its frame, presses at the next and releases at the one after.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "app/menu/imgui_session.h"
#include "app/menu/menu_panel.h"

namespace sandstorm {

class MenuScript {
 public:
  struct Click {
    std::uint32_t frame = 0;
    std::string widget;  // empty: close
    float across = 0.5f;
  };

  static MenuScript load(const std::filesystem::path& path);  // throws Error "file:line: ..."
  static MenuScript parse(const std::string& text, const std::string& name);

  // Before ImGuiSession::begin() of `frame`: injects this frame's input.
  void inject(std::uint32_t frame, ImGuiSession& session, const MenuPanel& panel) const;
  // Whether the script closes the window at or before `frame`.
  bool closesBy(std::uint32_t frame) const;
  const std::vector<Click>& clicks() const { return clicks_; }

 private:
  std::vector<Click> clicks_;
};

}  // namespace sandstorm
