#include "app/menu/legend_widget.h"

#include <imgui.h>

#include <algorithm>

namespace sandstorm {
namespace {

ImU32 packed(glm::vec3 c) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c.x, c.y, c.z, 1.0f));
}

}  // namespace

void drawColorLegend(const ColorScale& scale, const ColorMap& map, float width) {
  // As many ticks as labels of a few characters fit, each label a gap apart.
  const float labelWidth = ImGui::CalcTextSize("-0.00").x * 1.8f;
  const ColorLegend legend = ColorLegend::of(scale, std::clamp(int(width / labelWidth), 2, 6));
  ImGui::TextUnformatted(legend.title.c_str());
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float height = ImGui::GetTextLineHeight() * 1.3f;
  const float tick = ImGui::GetTextLineHeight() * 0.4f;
  constexpr int kSegments = 90;  // one per interval of the GPU's table
  for (int i = 0; i < kSegments; ++i) {
    const float t0 = float(i) / kSegments, t1 = float(i + 1) / kSegments;
    const ImU32 left = packed(map.at(t0)), right = packed(map.at(t1));
    draw->AddRectFilledMultiColor(ImVec2(at.x + t0 * width, at.y),
                                  ImVec2(at.x + t1 * width, at.y + height), left, right, right,
                                  left);
  }
  const ImU32 ink = ImGui::GetColorU32(ImGuiCol_Text);
  draw->AddRect(at, ImVec2(at.x + width, at.y + height), ink);
  float free = at.x;  // labels start right of here (none overlaps the one before)
  for (const LegendTick& t : legend.ticks) {
    const float x = at.x + t.t * width;
    draw->AddLine(ImVec2(x, at.y + height), ImVec2(x, at.y + height + tick), ink);
    const float textWidth = ImGui::CalcTextSize(t.label.c_str()).x;
    const float left = std::clamp(x - 0.5f * textWidth, at.x, at.x + width - textWidth);
    if (left < free) continue;
    draw->AddText(ImVec2(left, at.y + height + tick), ink, t.label.c_str());
    free = left + textWidth + ImGui::CalcTextSize(" ").x;
  }
  ImGui::Dummy(ImVec2(width, height + tick + ImGui::GetTextLineHeight()));
  if (!scale.note.empty()) ImGui::TextWrapped("%s", scale.note.c_str());
}

}  // namespace sandstorm
