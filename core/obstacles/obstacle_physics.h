// What obstacles do to the flow and to the particles: the twin of
// shaders/obstacles.glsl, operation for operation (the GPU/CPU agreement
// tests compare them bit for bit on llvmpipe). particle_physics.cpp calls
// these from fieldAt() and advance().
#pragma once

#include <span>

#include <glm/glm.hpp>

#include "core/field/height_map.h"
#include "core/obstacles/obstacle.h"

namespace sandstorm {

// Particles pushed out of an obstacle land this far outside its surface, so
// that rounding never leaves them a hair inside (m).
inline constexpr float kObstacleMargin = 1e-4f;

// The signed distance from x to the obstacle's surface (negative inside) and
// the outward normal there (the distance's gradient).
struct ObstacleSurface {
  float distance = 0.0f;
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
};
ObstacleSurface obstacleSurface(const Obstacle& o, const glm::vec3& x);

// A sphere's potential-flow strength R^3 / 2 (the GPU block carries it).
inline float sphereStrength(const Obstacle& o) {
  return 0.5f * o.radius * o.radius * o.radius;
}

// The field value f at x with the flow around every obstacle whose `flow` is
// on. `velocityField`: f is a velocity (tracer and drag models), so the stream
// an obstacle sees is f minus its own velocity; a force field is turned as it is.
// - Sphere: the potential flow past a sphere in the local stream u,
//   f + R^3 / (2 r^3) (u - 3 (u.n) n) outside (r the distance from the centre,
//   n its direction; r = R inside): at the surface the flow is tangent (relative
//   to the sphere), far away it is f. Exact for a uniform stream.
// - Box, cylinder: no closed form; the stream's normal component is removed
//   in a layer as thick as the shape's smallest half-extent, fading out
//   smoothly (smoothstep) across it, so the flow is tangent at the surface.
// Terms add: each obstacle's is computed from f itself.
glm::vec3 flowAroundObstacles(const glm::vec3& f, const glm::vec3& x,
                              std::span<const Obstacle> obstacles, bool velocityField);

// After a step: x inside the obstacle goes back to the nearest surface point
// (plus kObstacleMargin) and v's component towards the surface, relative to
// the obstacle, bounces with its restitution. With `terrain` (ground
// collision), a particle the nearest-point push would put under the ground
// leaves the obstacle straight up instead. Returns whether it was inside.
bool pushOutOfObstacle(const Obstacle& o, glm::vec3& x, glm::vec3& v, const HeightMap* terrain);

// After a step: out of every obstacle. pushOutOfObstacle for each in order;
// then, where one push put the particle into another solid (overlapping
// shapes, like the helicopter's boom and fuselage), it leaves straight up
// until it is in none: a column meets each shape in one interval, so rising
// never re-enters a shape it left and this ends within as many passes as
// there are shapes. No particle ends a step inside any obstacle.
void keepOutOfObstacles(std::span<const Obstacle> obstacles, glm::vec3& x, glm::vec3& v,
                        const HeightMap* terrain);

}  // namespace sandstorm
