// LegendHost: the colour legend shown on one wall (render.legend), and the
// probe's reading (probe.enabled) under it, built with
// Dear ImGui on the main thread each frame from the state and field it is
// given (the main context's, or on another cluster rank its StateMirror's),
// and handed to that wall's thread as UiDrawData like the menu.
// It takes no input. Its font atlas is ImGui's default, the same as the menu's.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "app/menu/imgui_session.h"
#include "core/sim/frame_packet.h"
#include "core/sim/particle_state.h"

namespace sandstorm {

class LegendHost {
 public:
  // `wallSize`: the legend's wall's image, in pixels (the legend sits in its
  // lower right corner).
  explicit LegendHost(glm::ivec2 wallSize);

  // `field`: the field the particles move in (the scale's range), or null.
  // `probe`: the probe's reading, shown under the bar (empty: none).
  void frame(float dt, const ParticleState& state, const FieldUpdate* field,
             const std::vector<std::string>& probe = {});
  // Null while render.legend is off and there is no probe.
  std::shared_ptr<const UiDrawData> latest() const;
  const UiFont& font() const { return session_.font(); }

 private:
  glm::ivec2 wallSize_;
  ImGuiSession session_;
  mutable std::mutex mutex_;
  std::shared_ptr<const UiDrawData> latest_;
};

}  // namespace sandstorm
