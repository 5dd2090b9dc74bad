// MenuPanel: the operator's panel (Dear ImGui), built on the main thread each
// frame. It edits the table of dynamic attributes (every entry gets a widget
// from its type and range), lists and edits emitters, starts, stops, pauses and
// resets the system (the thesis's F10), loads fields, and shows statistics.
// Every edit goes through the MainContext, which validates it and hands it to
// every wall at the same frame.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/sim/main_context.h"

namespace sandstorm {

struct MenuWallStats {
  std::string name;
  double fps = 0, frameMs = 0, updateMs = 0, renderMs = 0, postMs = 0, uploadMs = 0;
  std::size_t live = 0, capacity = 0;
  std::size_t molecules = 0;
};

struct MenuTrackingStats {
  std::string source;
  std::uint64_t received = 0, dropped = 0;
  std::uint64_t foreign = 0;  // from hosts not in tracking.sender
  bool waiting = true;        // nothing measured yet
  bool lost = false;          // no fresh measurement: the last poses are held
  std::uint32_t trackerFrame = 0;
  std::string lastError;
  bool wandTracked = false, wandPresent = false;
};

struct MenuStats {
  std::uint32_t frame = 0;
  std::vector<MenuWallStats> walls;
  std::optional<MenuTrackingStats> tracking;
  std::vector<std::string> probe;  // the probe's reading, a line each (empty: no probe)
};

class MenuPanel {
 public:
  // Loads a field by name or path and hands it to the main context; throws Error.
  using FieldLoader = std::function<void(const std::string& source)>;
  // Writes the field editor's composition to a path: a .toml block, or the
  // composed grid as .vti/.vdb; throws Error.
  using FieldWriter = std::function<void(const std::string& path)>;

  MenuPanel(MainContext& main, std::vector<std::string> fieldChoices, FieldLoader loader,
            FieldWriter writer = nullptr);

  // Between ImGuiSession::begin() and end().
  void build(const MenuStats& stats);

  // Where each widget was drawn last frame, by attribute key or button name
  // ("button:reset"): scripted input aims at these.
  struct Rect {
    glm::vec2 min, max;
  };
  const std::map<std::string, Rect>& rects() const { return rects_; }
  // The whole panel, as drawn last frame (the wand points at it).
  Rect panelRect() const { return panel_; }
  const std::string& lastMessage() const { return message_; }

 private:
  void attributeWidget(const AttributeInfo& info, const std::string& key,
                       const ParticleState& state);
  // A time-varying field: where playback stands, the steps in memory, waits and errors.
  void playbackStatus();
  void runControls(const ParticleState& state);
  void emitterSection(const ParticleState& state);
  void obstacleSection(const ParticleState& state);
  void moleculeSection(const MenuStats& stats, const ParticleState& state);
  void fieldSection(const ParticleState& state);
  void editorSection(const ParticleState& state);
  void statsSection(const MenuStats& stats, const ParticleState& state);
  void trackingSection(const MenuTrackingStats& tracking);
  void remember(const std::string& key);
  void apply(const std::string& key, const AttributeValue& value);

  MainContext& main_;
  std::vector<std::string> fieldChoices_;
  FieldLoader loader_;
  FieldWriter writer_;
  int selectedPrimitive_ = 0;
  std::string editorPath_ = "composed.toml";
  int selectedEmitter_ = 0;
  int selectedObstacle_ = 0;
  int selectedField_ = 0;
  std::string message_;
  std::map<std::string, std::string> typing_;  // expression boxes: what is typed, by key
  std::map<std::string, Rect> rects_;
  Rect panel_{};
};

}  // namespace sandstorm
