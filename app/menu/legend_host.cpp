#include "app/menu/legend_host.h"

#include <imgui.h>

#include <algorithm>

#include "app/menu/legend_widget.h"
#include "core/sim/state_color_scale.h"

namespace sandstorm {

LegendHost::LegendHost(glm::ivec2 wallSize) : wallSize_(wallSize), session_(nullptr, wallSize) {}

void LegendHost::frame(float dt, const ParticleState& state, const FieldUpdate* field,
                       const std::vector<std::string>& probe) {
  std::shared_ptr<const UiDrawData> data;
  if (state.render.legend || !probe.empty()) {
    const RenderSettings& r = state.render;
    const ColorScale scale = stateColorScale(state, field);
    // Large enough to read on a CAVE wall from its middle: a quarter of the
    // wall's width, text one and a half times the menu's.
    const float width = std::clamp(0.25f * float(wallSize_.x), 160.0f, 640.0f);
    session_.begin(dt);
    ImGui::SetNextWindowPos(ImVec2(float(wallSize_.x) - 12.0f, float(wallSize_.y) - 12.0f),
                            ImGuiCond_Always, ImVec2(1.0f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.55f);
    ImGui::Begin("Legend", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    ImGui::SetWindowFontScale(width >= 320.0f ? 1.5f : 1.0f);
    if (state.render.legend)
      drawColorLegend(scale, ColorMap(r.colorMap, r.colorBirth, r.colorDeath), width);
    for (const std::string& line : probe)
      ImGui::TextUnformatted(line.c_str());
    ImGui::End();
    data = session_.end();
  }
  std::lock_guard lock(mutex_);
  latest_ = std::move(data);
}

std::shared_ptr<const UiDrawData> LegendHost::latest() const {
  std::lock_guard lock(mutex_);
  return latest_;
}

}  // namespace sandstorm
