// View: how one image sees the room: a view and a projection matrix and the
// eye they belong to (billboards turn to face this eye). Room coordinates are
// metres, z up.
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

struct View {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::vec3 eye{0.0f};
};

// A conventional perspective camera (the desktop configuration).
View perspectiveView(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up,
                     float fovYRadians, float aspect, float nearPlane, float farPlane);

// Camera-space distance of a projected depth value in [0, 1], for any
// glm::perspective or glm::frustum projection.
float viewDistance(const glm::mat4& projection, float depth01);

}  // namespace sandstorm
