// Particle: one record of the particle buffers, laid out as the GPU stores it
// (the thesis's figure 5.1: two vec4 vertex buffers).
//   positionLife  = (x, y, z, remaining life in s)
//   velocityKind  = (vx, vy, vz, kind)
// kind > 0 marks a particle and holds the lifetime it was born with (so age and
// colour over life need no third buffer); kind < 0 marks an emitter record in
// the emission pass, which never reaches the particle buffers.
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

struct Particle {
  glm::vec4 positionLife{0.0f};
  glm::vec4 velocityKind{0.0f};

  glm::vec3 position() const { return glm::vec3(positionLife); }
  glm::vec3 velocity() const { return glm::vec3(velocityKind); }
  float life() const { return positionLife.w; }
  float lifetime() const { return velocityKind.w; }
  float age() const { return velocityKind.w - positionLife.w; }
};

static_assert(sizeof(Particle) == 32, "the GPU layout is two tightly packed vec4");

}  // namespace sandstorm
