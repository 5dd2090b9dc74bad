#include "app/menu/menu_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/menu/legend_widget.h"
#include "core/sim/state_color_scale.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

std::string labelOf(const std::string& key) {
  return key.substr(key.rfind('.') + 1);
}

}  // namespace

MenuPanel::MenuPanel(MainContext& main, std::vector<std::string> fieldChoices, FieldLoader loader,
                     FieldWriter writer)
    : main_(main),
      fieldChoices_(std::move(fieldChoices)),
      loader_(std::move(loader)),
      writer_(std::move(writer)) {}

void MenuPanel::remember(const std::string& key) {
  // The item's frame, without the label that follows it: a fraction across
  // a slider then means that fraction of its range.
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  rects_[key] = Rect{{a.x, a.y}, {std::min(b.x, a.x + ImGui::CalcItemWidth()), b.y}};
}

void MenuPanel::apply(const std::string& key, const AttributeValue& value) {
  try {
    const AttributeResult r = main_.set(key, value);
    message_ = r.warning.empty() ? key + " = " + toString(r.applied) : r.warning;
  } catch (const Error& e) {
    message_ = e.what();
    log::warn("menu: ", e.what());
  }
}

void MenuPanel::build(const MenuStats& stats) {
  const ParticleState state = main_.pendingState();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(ImVec2(360, 0),
                                      ImVec2(380, std::max(display.y - 16.0f, 100.0f)));
  ImGui::Begin(
      "Sandstorm", nullptr,
      ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize);
  runControls(state);
  statsSection(stats, state);
  if (state.helicopter.enabled &&
      ImGui::CollapsingHeader("Helicopter", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (const char* key :
         {"helicopter.throttle", "helicopter.altitude", "helicopter.x", "helicopter.y",
          "helicopter.wand_throttle", "helicopter.collide", "helicopter.collide_rotor"})
      attributeWidget(AttributeTable::instance().lookup(key), key, state);
  }
  // The thesis's Table 5.1 first: the attributes an operator reaches for.
  if (ImGui::CollapsingHeader("Table of dynamic attributes", ImGuiTreeNodeFlags_DefaultOpen)) {
    const AttributeTable& table = AttributeTable::instance();
    for (const char* key :
         {"render.size", "emitter.0.lifetime", "emitter.0.width", "emitter.0.depth", "sim.maximum",
          "emitter.0.position", "emitter.0.rate"})
      if (std::string(key).starts_with("emitter.") && state.emitters.empty())
        continue;
      else
        attributeWidget(table.lookup(key), key, state);
  }
  if (ImGui::CollapsingHeader("System")) {
    for (const AttributeInfo& info : AttributeTable::instance().entries())
      if (info.key.starts_with("sim.") && info.key != "sim.emitting" && info.key != "sim.paused")
        attributeWidget(info, info.key, state);
  }
  if (ImGui::CollapsingHeader("Look")) {
    const RenderSettings& r = state.render;
    drawColorLegend(stateColorScale(state, main_.field().get()),
                    ColorMap(r.colorMap, r.colorBirth, r.colorDeath), 320.0f);
    for (const AttributeInfo& info : AttributeTable::instance().entries())
      if (info.key.starts_with("render.")) attributeWidget(info, info.key, state);
  }
  if (ImGui::CollapsingHeader("Streamlines")) {
    for (const AttributeInfo& info : AttributeTable::instance().entries())
      if (info.key.starts_with("streamlines.")) attributeWidget(info, info.key, state);
  }
  if (ImGui::CollapsingHeader("Slice")) {
    for (const AttributeInfo& info : AttributeTable::instance().entries())
      if (info.key.starts_with("slice.")) attributeWidget(info, info.key, state);
  }
  if (ImGui::CollapsingHeader("Probe")) {
    for (const AttributeInfo& info : AttributeTable::instance().entries())
      if (info.key.starts_with("probe.")) attributeWidget(info, info.key, state);
  }
  emitterSection(state);
  moleculeSection(stats, state);
  obstacleSection(state);
  fieldSection(state);
  editorSection(state);
  if (ImGui::CollapsingHeader("Field playback")) {
    playbackStatus();
    for (const AttributeInfo& info : AttributeTable::instance().entries())
      if (info.key.starts_with("field.")) attributeWidget(info, info.key, state);
  }
  if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
  const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  panel_ = Rect{{at.x, at.y}, {at.x + size.x, at.y + size.y}};
  ImGui::End();
}

void MenuPanel::playbackStatus() {
  const FieldPlaybackStatus s = main_.fieldStatus();
  if (s.steps <= 1) return;
  ImGui::Text("t = %.3f s: steps %zu-%zu of %zu", s.time, s.first, s.second, s.steps);
  if (s.streamed) {
    // The loaded range over the series: which steps are in memory now.
    std::string held;
    for (std::size_t i = 0; i < s.resident.size(); ++i) {
      const bool runStart = i == 0 || s.resident[i] != s.resident[i - 1] + 1;
      const bool runEnd = i + 1 == s.resident.size() || s.resident[i + 1] != s.resident[i] + 1;
      if (runStart) held += (held.empty() ? "" : ", ") + std::to_string(s.resident[i]);
      if (runEnd && !runStart) held += "-" + std::to_string(s.resident[i]);
    }
    ImGui::Text("in memory: steps %s", held.c_str());
    const float width = ImGui::GetContentRegionAvail().x;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float height = ImGui::GetTextLineHeight() * 0.6f;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(at, ImVec2(at.x + width, at.y + height), IM_COL32(60, 60, 60, 255));
    const float step = width / float(s.steps);
    for (std::size_t i : s.resident)
      draw->AddRectFilled(ImVec2(at.x + step * float(i), at.y),
                          ImVec2(at.x + step * float(i + 1) + 1.0f, at.y + height),
                          IM_COL32(90, 160, 230, 255));
    draw->AddRectFilled(ImVec2(at.x + step * float(s.first), at.y - 2.0f),
                        ImVec2(at.x + step * float(s.first) + 2.0f, at.y + height + 2.0f),
                        IM_COL32(255, 255, 255, 255));
    ImGui::Dummy(ImVec2(width, height + 2.0f));
  }
  if (!s.waitingFor.empty())
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.2f, 1.0f), "waiting for %s", s.waitingFor.c_str());
  if (!s.error.empty())
    ImGui::TextColored(ImVec4(1.0f, 0.3f, 0.2f, 1.0f), "stopped: %s", s.error.c_str());
}

void MenuPanel::runControls(const ParticleState& state) {
  if (ImGui::Button(state.sim.emitting ? "Stop" : "Start"))
    apply("sim.emitting", !state.sim.emitting);
  remember("button:start");
  ImGui::SameLine();
  if (ImGui::Button(state.sim.paused ? "Resume" : "Pause")) apply("sim.paused", !state.sim.paused);
  remember("button:pause");
  ImGui::SameLine();
  if (ImGui::Button("Reset")) {
    main_.reset();
    message_ = "reset: every particle removed";
  }
  remember("button:reset");
}

void MenuPanel::statsSection(const MenuStats& stats, const ParticleState& state) {
  if (!ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::Text("frame %u", stats.frame);
  if (ImGui::BeginTable("walls", 7, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) {
    for (const char* h : {"wall", "fps", "frame ms", "update", "render", "post", "field"})
      ImGui::TableSetupColumn(h);
    ImGui::TableHeadersRow();
    for (const MenuWallStats& w : stats.walls) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(w.name.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.1f", w.fps);
      for (double ms : {w.frameMs, w.updateMs, w.renderMs, w.postMs, w.uploadMs}) {
        ImGui::TableNextColumn();
        ImGui::Text("%.2f", ms);
      }
    }
    ImGui::EndTable();
  }
  if (!stats.walls.empty()) {
    const MenuWallStats& w = stats.walls.front();
    const float fraction = state.sim.maximum > 0 ? float(w.live) / float(state.sim.maximum) : 0.0f;
    const std::string label = std::to_string(w.live) + " / " + std::to_string(state.sim.maximum) +
                              " (buffer " + std::to_string(w.capacity) + ")";
    ImGui::ProgressBar(std::min(fraction, 1.0f), ImVec2(-1, 0), label.c_str());
  }
  if (stats.tracking) trackingSection(*stats.tracking);
  for (const std::string& line : stats.probe)
    ImGui::TextUnformatted(line.c_str());
}

void MenuPanel::trackingSection(const MenuTrackingStats& t) {
  ImGui::Text("tracking: %s", t.source.c_str());
  if (t.waiting)
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.2f, 1.0f), "waiting for the tracker");
  else if (t.lost)
    ImGui::TextColored(ImVec4(1.0f, 0.3f, 0.2f, 1.0f), "tracking lost: holding the last pose");
  else
    ImGui::Text("tracker frame %u", t.trackerFrame);
  ImGui::Text("received %llu, dropped %llu", static_cast<unsigned long long>(t.received),
              static_cast<unsigned long long>(t.dropped));
  if (!t.lastError.empty() && ImGui::IsItemHovered())
    ImGui::SetTooltip("last refused: %s", t.lastError.c_str());
  if (t.foreign > 0)
    ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.2f, 1.0f), "from other hosts, dropped: %llu",
                       static_cast<unsigned long long>(t.foreign));
  if (!t.waiting)
    ImGui::Text("wand: %s", !t.wandPresent ? "not heard" : t.wandTracked ? "tracked" : "untracked");
}

void MenuPanel::emitterSection(const ParticleState& state) {
  if (!ImGui::CollapsingHeader("Emitters")) return;
  const int count = int(state.emitters.size());
  selectedEmitter_ = std::clamp(selectedEmitter_, 0, std::max(count - 1, 0));
  for (int i = 0; i < count; ++i) {
    const std::string shape = std::get<std::string>(
        AttributeTable::instance().get(state, "emitter." + std::to_string(i) + ".shape"));
    const std::string label = "emitter " + std::to_string(i) + " (" + shape + ")";
    if (ImGui::Selectable(label.c_str(), selectedEmitter_ == i)) selectedEmitter_ = i;
    remember("emitter:" + std::to_string(i));
  }
  if (ImGui::Button("Add")) {
    try {
      main_.addEmitter(count > 0 ? state.emitters[std::size_t(selectedEmitter_)] : Emitter{});
      selectedEmitter_ = count;
      message_ = "added emitter " + std::to_string(count);
    } catch (const Error& e) {
      message_ = e.what();
    }
  }
  remember("button:add-emitter");
  ImGui::SameLine();
  if (ImGui::Button("Remove") && count > 0) {
    try {
      main_.removeEmitter(selectedEmitter_);
      message_ = "removed emitter " + std::to_string(selectedEmitter_);
    } catch (const Error& e) {
      message_ = e.what();
    }
  }
  remember("button:remove-emitter");
  if (count == 0) return;
  const std::string prefix = "emitter." + std::to_string(selectedEmitter_) + ".";
  for (const AttributeInfo& info : AttributeTable::instance().entries())
    if (info.perEmitter()) attributeWidget(info, prefix + info.key.substr(10), state);
}

// The obstacles of the configuration ([[obstacle]]): pick one, edit it. The
// mouse drags them on the floor and the wand grabs them too.
void MenuPanel::obstacleSection(const ParticleState& state) {
  const bool open = ImGui::CollapsingHeader("Obstacles");
  remember("header:obstacles");
  if (!open) return;
  const int count = int(state.obstacles.size());
  if (count == 0) {
    ImGui::TextWrapped("none: add [[obstacle]] tables to the configuration");
    return;
  }
  selectedObstacle_ = std::clamp(selectedObstacle_, 0, count - 1);
  for (int i = 0; i < count; ++i) {
    const std::string shape = std::get<std::string>(
        AttributeTable::instance().get(state, "obstacle." + std::to_string(i) + ".shape"));
    const std::string label = "obstacle " + std::to_string(i) + " (" + shape + ")";
    if (ImGui::Selectable(label.c_str(), selectedObstacle_ == i)) selectedObstacle_ = i;
    remember("obstacle:" + std::to_string(i));
  }
  for (const AttributeInfo& info : AttributeTable::instance().entries())
    if (info.perObstacle()) attributeWidget(info, info.itemKey(selectedObstacle_), state);
}

// The molecules (core/molecules): how many, their shape and springs, the
// push tool. An emitter makes them when its kind is molecules (Emitters).
void MenuPanel::moleculeSection(const MenuStats& stats, const ParticleState& state) {
  const bool open = ImGui::CollapsingHeader("Molecules");
  remember("header:molecules");
  if (!open) return;
  int emitters = 0;
  for (const Emitter& e : state.emitters)
    emitters += e.kind == EmitterKind::Molecules ? 1 : 0;
  if (emitters == 0)
    ImGui::TextWrapped("no emitter makes molecules: set an emitter's kind to molecules (Emitters)");
  const std::size_t live = stats.walls.empty() ? 0 : stats.walls.front().molecules;
  const int maximum = state.molecules.maximum;
  const std::string label = std::to_string(live) + " / " + std::to_string(maximum) + " molecules";
  ImGui::ProgressBar(maximum > 0 ? std::min(float(live) / float(maximum), 1.0f) : 0.0f,
                     ImVec2(-1, 0), label.c_str());
  for (const AttributeInfo& info : AttributeTable::instance().entries())
    if (info.key.starts_with("molecules.")) attributeWidget(info, info.key, state);
}

// The field: another one from the data folder, and the live flow solver.
void MenuPanel::fieldSection(const ParticleState& state) {
  const bool open = ImGui::CollapsingHeader("Field");
  remember("header:field");
  if (!open) return;
  if (!fieldChoices_.empty()) {
    selectedField_ = std::clamp(selectedField_, 0, int(fieldChoices_.size()) - 1);
    if (ImGui::BeginCombo("source", fieldChoices_[std::size_t(selectedField_)].c_str())) {
      for (int i = 0; i < int(fieldChoices_.size()); ++i)
        if (ImGui::Selectable(fieldChoices_[std::size_t(i)].c_str(), i == selectedField_))
          selectedField_ = i;
      ImGui::EndCombo();
    }
    remember("field:source");
    if (ImGui::Button("Load field")) {
      try {
        loader_(fieldChoices_[std::size_t(selectedField_)]);
        message_ = "loaded " + fieldChoices_[std::size_t(selectedField_)];
      } catch (const Error& e) {
        message_ = e.what();
      }
    }
    remember("button:load-field");
  }
  ImGui::TextUnformatted("live flow solver");
  for (const AttributeInfo& info : AttributeTable::instance().entries())
    if (info.key.starts_with("solver.")) attributeWidget(info, info.key, state);
}

// The field editor (core/editor): eight slots of primitives added to the
// field. A slot's kind fills it (none empties it); the mouse drags a
// primitive's ball on the floor and the wand grabs it. The composition is
// saved as a configuration block (.toml) or baked to a grid (.vti, .vdb).
void MenuPanel::editorSection(const ParticleState& state) {
  const bool open = ImGui::CollapsingHeader("Field editor");
  remember("header:editor");
  if (!open) return;
  const int count = int(state.primitives.size());
  selectedPrimitive_ = std::clamp(selectedPrimitive_, 0, std::max(count - 1, 0));
  // The slots on one row (a filled one marked *), then the chosen slot's attributes.
  for (int i = 0; i < count; ++i) {
    const bool filled = state.primitives[std::size_t(i)].kind != PrimitiveKind::None;
    if (i > 0) ImGui::SameLine();
    const std::string label = std::to_string(i) + (filled ? "*" : "");
    if (ImGui::RadioButton(label.c_str(), selectedPrimitive_ == i)) selectedPrimitive_ = i;
    remember("primitive:" + std::to_string(i));
  }
  if (count == 0) return;
  for (const AttributeInfo& info : AttributeTable::instance().entries())
    if (info.perPrimitive()) attributeWidget(info, info.itemKey(selectedPrimitive_), state);
  const std::string prefix = "primitive." + std::to_string(selectedPrimitive_) + ".";
  if (ImGui::Button("Remove")) apply(prefix + "kind", std::string("none"));
  remember("button:remove-primitive");
  if (!writer_) return;
  ImGui::SameLine();
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, "%s", editorPath_.c_str());
  if (ImGui::InputText("file", buffer, sizeof buffer)) editorPath_ = buffer;
  remember("editor:file");
  // Save writes the .toml block; Bake the grid, .vti unless a .vdb is named.
  const auto write = [&](const char* label, const char* button, const char* done,
                         const char* extension, bool orVdb) {
    if (ImGui::Button(label)) {
      std::filesystem::path path = editorPath_;
      if (path.extension() != extension && !(orVdb && path.extension() == ".vdb"))
        path.replace_extension(extension);
      try {
        writer_(path.string());
        message_ = std::string(done) + " " + path.string();
      } catch (const Error& e) {
        message_ = e.what();
      }
    }
    remember(button);
  };
  write("Save", "button:save-field", "saved", ".toml", false);
  ImGui::SameLine();
  write("Bake", "button:bake-field", "baked", ".vti", true);
}

void MenuPanel::attributeWidget(const AttributeInfo& info, const std::string& key,
                                const ParticleState& state) {
  const AttributeValue value = AttributeTable::instance().get(state, key);
  const std::string label =
      labelOf(key) + (info.unit.empty() || info.unit == "rgb" ? "" : " (" + info.unit + ")");
  ImGui::PushID(key.c_str());
  switch (info.type) {
    case AttributeType::Bool: {
      bool v = std::get<bool>(value);
      if (ImGui::Checkbox(label.c_str(), &v)) apply(key, v);
      break;
    }
    case AttributeType::Int: {
      int v = std::get<int>(value);
      if (ImGui::SliderInt(label.c_str(), &v, int(info.min), int(std::min(info.max, 1e7f)), "%d",
                           ImGuiSliderFlags_Logarithmic))
        apply(key, v);
      break;
    }
    case AttributeType::Float: {
      float v = std::get<float>(value);
      const bool wide = info.max - info.min > 100.0f;
      const float hi = wide ? std::min(info.max, std::max(1e5f, 10.0f * std::abs(v))) : info.max;
      if (ImGui::SliderFloat(label.c_str(), &v, info.min, hi, "%.4g",
                             wide ? ImGuiSliderFlags_Logarithmic : 0))
        apply(key, v);
      break;
    }
    case AttributeType::Vec3: {
      glm::vec3 v = std::get<glm::vec3>(value);
      const bool changed = info.unit == "rgb"
                               ? ImGui::ColorEdit3(label.c_str(), &v.x)
                               : ImGui::DragFloat3(label.c_str(), &v.x, 0.01f, info.min, info.max);
      if (changed) apply(key, v);
      break;
    }
    case AttributeType::Enum: {
      const std::string current = std::get<std::string>(value);
      if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
        for (const std::string& choice : info.choices)
          if (ImGui::Selectable(choice.c_str(), choice == current)) apply(key, choice);
        ImGui::EndCombo();
      }
      break;
    }
    case AttributeType::Expression: {
      // Typed text, applied with Enter; a refused one stays in the box with
      // the message below (the field keeps the last good one).
      std::string& text = typing_[key];
      if (!ImGui::IsItemActive() && text.empty()) text = std::get<std::string>(value);
      char buffer[kMaxExpressionLength + 1];
      std::snprintf(buffer, sizeof buffer, "%s", text.c_str());
      if (ImGui::InputText(label.c_str(), buffer, sizeof buffer,
                           ImGuiInputTextFlags_EnterReturnsTrue)) {
        text = buffer;
        apply(key, text);
        if (std::get<std::string>(AttributeTable::instance().get(main_.pendingState(), key)) ==
            text)
          text.clear();  // applied: show the state's from now on
      } else if (ImGui::IsItemActive()) {
        text = buffer;
      }
      break;
    }
    case AttributeType::Name: {
      // The one name attribute, render.color_array, picks among the field's scalar arrays.
      const std::string current = std::get<std::string>(value);
      const std::shared_ptr<const FieldUpdate> field = main_.field();
      const char* first = "(the field's first)";
      if (ImGui::BeginCombo(label.c_str(), current.empty() ? first : current.c_str())) {
        if (ImGui::Selectable(first, current.empty())) apply(key, std::string());
        if (field && field->field) {
          for (const VectorField::Scalars& a : field->field->scalars())
            if (ImGui::Selectable(a.name.c_str(), a.name == current)) apply(key, a.name);
          if (field->field->scalars().empty())
            ImGui::TextDisabled("the field carries no scalar arrays");
        }
        ImGui::EndCombo();
      }
      break;
    }
  }
  remember(key);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s\n%s", key.c_str(), info.description.c_str());
  ImGui::PopID();
}

}  // namespace sandstorm
