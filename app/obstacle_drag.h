// ObstacleDrag: the desktop's mouse moves obstacles as in the Mali sample: a
// left press on an obstacle grabs it, and dragging slides it along the floor
// (the grabbed point stays under the cursor, at its height); its velocity is
// the drag's, so the flow and the bounces feel the motion, and it comes to
// rest when released. Each move is an attribute change (every wall moves it
// at one frame; --record keeps it).
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "core/cave/wall_views.h"
#include "core/sim/main_context.h"

namespace sandstorm {

class ObstacleDrag {
 public:
  // At a left press: grabs the nearest obstacle the ray meets; false for none.
  bool pick(const ParticleState& state, const WorldRay& ray);
  // While held (`released` on the last call): follows the ray; dt in seconds.
  void drag(MainContext& main, const WorldRay& ray, float dt, bool released);
  bool holding() const { return index_.has_value(); }

 private:
  std::optional<int> index_;
  float grabHeight_ = 0.0f;
  glm::vec3 offset_{0.0f};  // from the grabbed point to the obstacle's centre
};

}  // namespace sandstorm
