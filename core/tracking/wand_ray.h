// The wand's ray and what it meets, in room metres: the menu panel on a wall,
// an emitter's handle, the ground (terrain). The main context casts it once a
// frame (WandController) and the result travels in the FramePacket, so every
// wall draws the same ray and the same hit, lined up across the seams.
#pragma once

#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "core/cave/viewer.h"
#include "core/cave/wall.h"
#include "core/field/height_map.h"

namespace sandstorm {

enum class WandTarget : std::uint8_t { None = 0, Menu = 1, Emitter = 2, Ground = 3 };

struct WandRay {
  bool visible = false;               // a tracked wand: draw it
  glm::vec3 origin{0.0f}, end{0.0f};  // room metres; `end` is the hit, or the ray's full length
  WandTarget target = WandTarget::None;
  int emitter = -1;      // the emitter pointed at or held, or -1
  bool holding = false;  // `emitter` is grabbed and moves with the wand

  bool operator==(const WandRay&) const = default;
};

struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 1.0f, 0.0f};  // unit
  glm::vec3 at(float t) const { return origin + t * direction; }
};

// Where a ray meets a wall's rectangle from either side: the distance and the
// wall coordinates (u along lower-left -> lower-right, v along lower-left -> upper-left, 0..1).
struct WallHit {
  float t = 0.0f;
  glm::vec2 uv{0.0f};
};
std::optional<WallHit> hitWall(const Ray& ray, const WallCorners& wall);

// The nearest t >= 0 where the ray enters a sphere (0 when it starts inside).
std::optional<float> hitSphere(const Ray& ray, const glm::vec3& centre, float radius);

// Where a ray in the room first reaches the ground, a height map in world
// coordinates seen through the navigation; searched up to maxT room metres.
std::optional<float> hitGround(const Ray& ray, const Navigation& navigation,
                               const HeightMap& ground, float maxT);

}  // namespace sandstorm
