// Obstacle: a solid the dust goes around and never enters: the Mali sample's
// sphere that the user drags across the floor, a box, a cylinder; and the
// moving scene objects of the thesis's future work (the helicopter's body,
// helicopter_shape.h). Room metres, z up; axis-aligned.
//
// Two effects, both in core/obstacles/obstacle_physics.h and its GLSL twin:
// - the flow goes around it (`flow`): a sphere adds the potential flow of a
//   sphere in the local stream; boxes and cylinders lose the stream's normal
//   component in a thin layer around them;
// - a particle that ends a step inside is put back on the surface, and its
//   velocity towards the surface (relative to the obstacle's) bounces with
//   `restitution`.
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

enum class ObstacleShape : int { Sphere = 0, Box = 1, Cylinder = 2 };

struct Obstacle {
  ObstacleShape shape = ObstacleShape::Sphere;
  glm::vec3 position{0.0f, 0.0f, 1.0f};  // m: the centre
  float radius = 0.5f;                   // m: sphere, cylinder
  glm::vec3 size{1.0f};                  // m: a box's full extent along x, y, z
  float height = 1.0f;                   // m: a cylinder's (its axis is vertical)
  // m/s: how fast it moves (its path and a mouse drag set it); the flow
  // around it and the bounces off it are relative to it.
  glm::vec3 velocity{0.0f};
  float restitution = 0.3f;  // fraction of the speed towards the surface kept on a bounce
  bool flow = true;          // the flow goes around it (off: particles only bounce)
  bool path = true;          // follows its scripted path, when the configuration gives one
  bool enabled = true;

  bool operator==(const Obstacle&) const = default;
};

}  // namespace sandstorm
