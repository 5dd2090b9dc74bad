// ObstacleDrag: the desktop's mouse moves obstacles as in the Mali sample, and
// the field editor's primitives the same way: a left press on an obstacle (or
// within 0.25 m of a primitive's ball) grabs it, and dragging slides it along
// the floor (the grabbed point stays under the cursor, at its height). An
// obstacle's velocity is the drag's, so the flow and the bounces feel the
// motion, and it comes to rest when released. Each move is an attribute
// change (every wall moves it at one frame; --record keeps it).
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "core/cave/wall_views.h"
#include "core/sim/main_context.h"

namespace sandstorm {

class ObstacleDrag {
 public:
  // At a left press: grabs the nearest obstacle or primitive the ray meets; false for none.
  bool pick(const ParticleState& state, const WorldRay& ray);
  // While held (`released` on the last call): follows the ray; dt in seconds.
  void drag(MainContext& main, const WorldRay& ray, float dt, bool released);
  bool holding() const { return held_.has_value(); }

 private:
  struct Held {
    std::string prefix;  // "obstacle.2." or "primitive.0."
    bool obstacle = true;
  };
  std::optional<Held> held_;
  float grabHeight_ = 0.0f;
  glm::vec3 offset_{0.0f};  // from the grabbed point to the item's position
};

}  // namespace sandstorm
