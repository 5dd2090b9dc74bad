// WandController: what the tracked wand does, decided once a frame on the
// main context from that frame's TrackingSample (so replays and every wall
// agree). It casts the ray (wand_ray.h) and turns buttons, tilt and joystick
// into requests:
//
// - menu: when the ray meets the menu panel on its wall, the hit in the wall
//   image's pixels and the trigger drive the menu's mouse;
// - grab: the grab button on a handle (an emitter, the streamline rake's
//   ends, the slice's point, the probe: wand_handles.h) picks the nearest one
//   along the ray; it then moves rigidly with the wand (its position
//   attribute) until the button is let go;
// - throttle (the thesis's helicopter control, helicopter.wand_throttle): the
//   wand tilted up, towards the user, raises helicopter.throttle, tilted down
//   lowers it, at a rate that grows with the tilt past a dead zone; the
//   throttle moves in steps of kThrottleStep so the wash is re-baked only then;
// - push (molecules.push_tool): the grab button held off a handle and the
//   menu blows molecules away from a point kPushReach ahead of the wand
//   (molecules.push, molecules.push_position) until it is let go;
// - flying ([navigation] fly_speed, turn_speed_deg): the joystick's y flies
//   along the wand's horizontal direction, its x turns the world about the
//   head's vertical axis. An occluded wand (untracked, its Flystick still
//   heard) has no ray, grabs nothing and clicks nothing, but still flies,
//   along the head's horizontal direction.
//
// Every request is an attribute change or a new navigation the caller hands
// to the main context, so each is validated, recorded and replayed.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/config/app_config.h"
#include "core/sim/attribute_table.h"
#include "core/sim/particle_state.h"
#include "core/tracking/tracking_sample.h"
#include "core/tracking/wand_ray.h"

namespace sandstorm {

// The menu panel as the wand can reach it: on a wall, at a pixel rectangle
// of one eye's image of that wall (the overlay's own coordinates, y down).
struct WandMenuTarget {
  WallSpec wall;         // corners, image size, stereo layout
  glm::ivec2 imageSize;  // the wall image's pixels
  glm::vec2 panelMin{0.0f}, panelMax{0.0f};
};

// What the wand can meet this frame.
struct WandScene {
  const ParticleState* state = nullptr;  // emitters (world), helicopter
  Navigation navigation;
  const HeightMap* ground = nullptr;  // null: none
  std::optional<WandMenuTarget> menu;
};

struct WandActions {
  WandRay ray;
  struct MenuPointer {
    glm::vec2 pixel{0.0f};
    bool down = false;
  };
  std::optional<MenuPointer> menu;
  std::vector<std::pair<std::string, AttributeValue>> sets;  // emitter moves, throttle
  std::optional<Navigation> navigation;                      // flying and turning
};

// A point on a wall in the pixels (y down) of one eye's image, where the
// overlays are laid out and drawn into each eye's (eyeImageSize: a half of a
// side-by-side or top-bottom image, else the whole image).
glm::vec2 wallPixel(const WallSpec& wall, glm::ivec2 imageSize, glm::vec2 uv);

class WandController {
 public:
  static constexpr float kThrottleStep = 0.02f;
  static constexpr float kTiltDeadZoneDeg = 15.0f;
  static constexpr float kTiltFullDeg = 50.0f;  // full rate from here
  static constexpr float kThrottleRate = 0.4f;  // per second at full tilt
  static constexpr float kJoystickDeadZone = 0.1f;
  static constexpr float kPushReach = 0.5f;  // m (room) ahead of the wand
  // The longest frame the throttle and flying integrate over: a stalled frame
  // (a shader compiled, a field re-baked) must not jump the throttle or the
  // user across the scene.
  static constexpr float kMaxFrameSeconds = 0.1f;

  WandController(const TrackingSpec& tracking, const NavigationSpec& navigation);

  WandActions update(const TrackingSample& sample, const WandScene& scene, float dt);

  // The handle held (its index in wandHandles()), or -1.
  int holding() const { return held_ ? held_->emitter : -1; }

 private:
  struct Held {
    int emitter = -1;       // the handle's index (wand_handles.h)
    std::string key;        // the attribute it moves
    glm::vec3 local{0.0f};  // the handle in the wand's frame (room metres)
    glm::vec3 lastWorld{0.0f};
  };
  void flyAndTurn(const TrackingSample& sample, const Navigation& navigation,
                  const glm::vec3& ahead, float dt, WandActions& out) const;

  TrackingSpec tracking_;
  NavigationSpec navigation_;
  std::uint32_t previousButtons_ = 0;
  std::optional<Held> held_;
  float throttleDrift_ = 0.0f;
  bool pushing_ = false;
};

}  // namespace sandstorm
