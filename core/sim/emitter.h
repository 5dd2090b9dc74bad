// Emitter: where, how often and with what initial state particles are born.
// The thesis's emission area is the box shape: AreaWidth x AreaDepth at Position.
// Coordinates are room metres, z up.
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

enum class EmitterShape : int { Box = 0, Sphere = 1, Disc = 2, Point = 3 };

// What it emits: single particles, or molecules (core/molecules/: small
// mass-spring meshes born and killed whole; the rate then counts molecules).
enum class EmitterKind : int { Particles = 0, Molecules = 1 };

struct Emitter {
  EmitterShape shape = EmitterShape::Box;
  glm::vec3 position{0.0f};
  float width = 1.0f;             // m, along x (box)
  float depth = 1.0f;             // m, along y (box)
  float height = 0.0f;            // m, along z (box)
  float radius = 0.5f;            // m (sphere, disc; the disc lies in the horizontal plane)
  float rate = 1000.0f;           // particles/s, Reeves' mean
  float rateVariance = 0.0f;      // particles/s, Reeves' variance: rate +- rateVariance
  float lifetime = 4.0f;          // s
  float lifetimeVariance = 0.0f;  // s: lifetime +- lifetimeVariance
  glm::vec3 velocity{0.0f};       // m/s at birth
  float spread = 0.0f;            // m/s: radius of the random ball added to velocity
  bool enabled = true;
  EmitterKind kind = EmitterKind::Particles;
};

}  // namespace sandstorm
