// LegendHost: the colour legend shown on one wall (render.legend), and the
// probe's reading (probe.enabled) under it, built with
// Dear ImGui on the main thread each frame from the main context's state and
// field range, and handed to that wall's thread as UiDrawData like the menu.
// It takes no input. Its font atlas is ImGui's default, the same as the menu's.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "app/menu/imgui_session.h"
#include "core/sim/main_context.h"

namespace sandstorm {

class LegendHost {
 public:
  // `wallSize`: the legend's wall's image, in pixels (the legend sits in its
  // lower right corner).
  LegendHost(const MainContext& main, glm::ivec2 wallSize);

  // `probe`: the probe's reading, shown under the bar (empty: none).
  void frame(float dt, const std::vector<std::string>& probe = {});
  // Null while render.legend is off and there is no probe.
  std::shared_ptr<const UiDrawData> latest() const;
  const UiFont& font() const { return session_.font(); }

 private:
  const MainContext& main_;
  glm::ivec2 wallSize_;
  ImGuiSession session_;
  mutable std::mutex mutex_;
  std::shared_ptr<const UiDrawData> latest_;
};

}  // namespace sandstorm
