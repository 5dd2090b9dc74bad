// MoleculePush: the molecules paper's push tool from the desktop's mouse.
// With molecules.push_tool on, a left press that picks no obstacle starts a
// push: molecules.push turns on at the point of the ray through the cursor
// nearest the field's centre (the molecules' middle), molecules.push_position
// follows the cursor while the button is held, and the push stops when it is
// let go. Each is an attribute change (every wall at one frame; --record keeps
// it). The tracked wand pushes through WandController.
#pragma once

#include <glm/glm.hpp>

#include "core/cave/wall_views.h"
#include "core/sim/main_context.h"

namespace sandstorm {

class MoleculePush {
 public:
  // At a left press: starts pushing when the push tool is on; false otherwise.
  bool press(MainContext& main, const WorldRay& ray, const glm::vec3& centre);
  // While held: follows the ray; stops when `released`.
  void drag(MainContext& main, const WorldRay& ray, const glm::vec3& centre, bool released);
  bool holding() const { return holding_; }

  // The point of the ray nearest `centre` (never behind its origin).
  static glm::vec3 pushPoint(const WorldRay& ray, const glm::vec3& centre);

 private:
  bool holding_ = false;
};

}  // namespace sandstorm
