#include "core/tracking/wand_controller.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/cave/wall_views.h"
#include "core/tracking/wand_handles.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

glm::mat3 rotationZ(float radians) {
  const float c = std::cos(radians), s = std::sin(radians);
  return glm::mat3(c, s, 0.0f, -s, c, 0.0f, 0.0f, 0.0f, 1.0f);
}

float deadZone(float v, float zone) {
  if (std::abs(v) <= zone) return 0.0f;
  return std::copysign((std::abs(v) - zone) / (1.0f - zone), v);
}

}  // namespace

glm::vec2 wallPixel(const WallSpec& wall, glm::ivec2 size, glm::vec2 uv) {
  const glm::vec2 eye = eyeImageSize(wall.stereo, glm::vec2(size));
  return {uv.x * eye.x, (1.0f - uv.y) * eye.y};
}

WandController::WandController(const TrackingSpec& tracking, const NavigationSpec& navigation)
    : tracking_(tracking), navigation_(navigation) {}

WandActions WandController::update(const TrackingSample& sample, const WandScene& scene,
                                   float frameSeconds) {
  const float dt = std::min(frameSeconds, kMaxFrameSeconds);
  WandActions out;
  const WandSample& wand = sample.wand;
  const std::uint32_t pressedNow = wand.present ? wand.buttons : 0u;
  const auto edge = [&](int button) {
    return button >= 0 && button < 32 && (pressedNow >> unsigned(button) & 1u) &&
           !(previousButtons_ >> unsigned(button) & 1u);
  };
  const bool grabDown = wand.pressed(tracking_.grabButton);
  const ParticleState* state = scene.state;
  const std::vector<WandHandle> handles = state ? wandHandles(*state) : std::vector<WandHandle>{};
  const int handleCount = int(handles.size());
  if (held_ && (held_->emitter >= handleCount ||
                handles[std::size_t(held_->emitter)].key != held_->key || !grabDown))
    held_.reset();

  if (!wand.tracked) {
    // Occluded: no ray, nothing grabbed; the joystick still flies, where the head looks.
    held_.reset();
    flyAndTurn(sample, scene.navigation, sample.head.forward(), dt, out);
    previousButtons_ = pressedNow;
    return out;
  }

  // The ray, and the nearest thing on it.
  const Ray ray{wand.pose.position, glm::normalize(wand.pose.forward())};
  out.ray.visible = true;
  out.ray.origin = ray.origin;
  float nearest = tracking_.rayLength;
  std::optional<glm::vec2> menuPixel;
  if (scene.menu) {
    if (const std::optional<WallHit> hit = hitWall(ray, scene.menu->wall.corners)) {
      const glm::vec2 pixel = wallPixel(scene.menu->wall, scene.menu->imageSize, hit->uv);
      if (hit->t < nearest && glm::all(glm::greaterThanEqual(pixel, scene.menu->panelMin)) &&
          glm::all(glm::lessThanEqual(pixel, scene.menu->panelMax))) {
        nearest = hit->t;
        menuPixel = pixel;
        out.ray.target = WandTarget::Menu;
      }
    }
  }
  for (int i = 0; i < handleCount && !held_; ++i) {
    const glm::vec3 handle = glm::vec3(scene.navigation.worldToRoom() *
                                       glm::vec4(handles[std::size_t(i)].position, 1.0f));
    if (const std::optional<float> t = hitSphere(ray, handle, tracking_.grabRadius);
        t && *t < nearest) {
      nearest = *t;
      menuPixel.reset();
      out.ray.target = WandTarget::Emitter;
      out.ray.emitter = i;
    }
  }
  if (scene.ground && !held_)
    if (const std::optional<float> t = hitGround(ray, scene.navigation, *scene.ground, nearest);
        t && *t < nearest) {
      nearest = *t;
      menuPixel.reset();
      out.ray.target = WandTarget::Ground;
      out.ray.emitter = -1;
    }
  out.ray.end = ray.at(nearest);

  // The menu takes the trigger while the ray is on it.
  if (menuPixel)
    out.menu = WandActions::MenuPointer{*menuPixel, wand.pressed(tracking_.triggerButton)};

  // Grab and carry.
  const glm::mat4 wandFrame(glm::vec4(wand.pose.axes[0], 0.0f), glm::vec4(wand.pose.axes[1], 0.0f),
                            glm::vec4(wand.pose.axes[2], 0.0f),
                            glm::vec4(wand.pose.position, 1.0f));
  if (!held_ && !menuPixel && edge(tracking_.grabButton) && out.ray.target == WandTarget::Emitter) {
    const WandHandle& handle = handles[std::size_t(out.ray.emitter)];
    const glm::vec3 room =
        glm::vec3(scene.navigation.worldToRoom() * glm::vec4(handle.position, 1.0f));
    held_ = Held{out.ray.emitter, handle.key,
                 glm::vec3(glm::inverse(wandFrame) * glm::vec4(room, 1.0f))};
    // What the carry below computes for the wand standing still: no change until it moves.
    held_->lastWorld =
        scene.navigation.roomToWorld(glm::vec3(wandFrame * glm::vec4(held_->local, 1.0f)));
  }
  if (held_) {
    const glm::vec3 room = glm::vec3(wandFrame * glm::vec4(held_->local, 1.0f));
    const glm::vec3 world = scene.navigation.roomToWorld(room);
    if (world != held_->lastWorld) {
      out.sets.emplace_back(held_->key, world);
      held_->lastWorld = world;
    }
    out.ray.holding = true;
    out.ray.emitter = held_->emitter;
    out.ray.target = WandTarget::Emitter;
    out.ray.end = room;
  }

  // The molecules' push tool: the grab button off a handle and the menu blows
  // molecules away from a point kPushReach ahead of the wand.
  const bool pushTool = state && state->molecules.pushTool;
  if (pushTool && !held_ && !menuPixel && edge(tracking_.grabButton) &&
      out.ray.target != WandTarget::Emitter)
    pushing_ = true;
  if (pushing_ && (!grabDown || !pushTool)) {
    pushing_ = false;
    out.sets.emplace_back("molecules.push", false);
  } else if (pushing_) {
    const glm::vec3 at = scene.navigation.roomToWorld(ray.at(kPushReach));
    if (!state->molecules.push) out.sets.emplace_back("molecules.push", true);
    if (at != state->molecules.pushPosition) out.sets.emplace_back("molecules.push_position", at);
    out.ray.end = ray.at(kPushReach);
  }

  // The thesis's throttle: tilt up (towards the user) raises it.
  if (state && state->helicopter.enabled && state->helicopter.wandThrottle && !held_ &&
      !menuPixel && !pushing_) {
    const float tilt = glm::degrees(std::asin(std::clamp(ray.direction.z, -1.0f, 1.0f)));
    const float beyond =
        std::max(std::abs(tilt) - kTiltDeadZoneDeg, 0.0f) / (kTiltFullDeg - kTiltDeadZoneDeg);
    throttleDrift_ += std::copysign(std::min(beyond, 1.0f), tilt) * kThrottleRate * dt;
    // Whole steps only, so the wash is re-baked a step at a time; the rest stays stored up.
    const float current = state->helicopter.throttle;
    const float steps = std::trunc(throttleDrift_ / kThrottleStep);
    if (steps != 0.0f) {
      // On the grid of steps, so repeated steps land on 0 and 1 exactly.
      const float next =
          std::clamp(std::round((current + steps * kThrottleStep) / kThrottleStep) * kThrottleStep,
                     0.0f, 1.0f);
      throttleDrift_ -= steps * kThrottleStep;
      if (next != current) out.sets.emplace_back("helicopter.throttle", next);
      if (next <= 0.0f || next >= 1.0f) throttleDrift_ = 0.0f;  // pinned: store nothing up
    }
  } else {
    throttleDrift_ = 0.0f;
  }

  flyAndTurn(sample, scene.navigation, ray.direction, dt, out);
  previousButtons_ = pressedNow;
  return out;
}

// Flying along `ahead` (level) and turning about the head with the joystick.
void WandController::flyAndTurn(const TrackingSample& sample, const Navigation& navigation,
                                const glm::vec3& ahead, float dt, WandActions& out) const {
  const WandSample& wand = sample.wand;
  const float fly = deadZone(wand.joystick.y, kJoystickDeadZone);
  const float turn = deadZone(wand.joystick.x, kJoystickDeadZone);
  if ((fly != 0.0f || turn != 0.0f) && dt > 0.0f) {
    Navigation n = navigation;
    const glm::vec3 flat(ahead.x, ahead.y, 0.0f);
    if (glm::length(flat) > 1e-3f)
      n.offset -= glm::normalize(flat) * (fly * navigation_.flySpeed * dt);
    if (turn != 0.0f) {
      // Joystick right turns the user right: the world turns the other way about the head.
      const float a = glm::radians(turn * navigation_.turnSpeedDeg * dt);
      const glm::vec3 pivot(sample.head.position.x, sample.head.position.y, 0.0f);
      n.offset = pivot + rotationZ(a) * (n.offset - pivot);
      n.yawRadians += a;
    }
    out.navigation = n;
  }
}

}  // namespace sandstorm
