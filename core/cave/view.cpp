#include "core/cave/view.h"

#include <glm/gtc/matrix_transform.hpp>

namespace sandstorm {

View perspectiveView(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up, float fovY,
                     float aspect, float nearPlane, float farPlane) {
  View v;
  v.view = glm::lookAt(eye, target, up);
  v.projection = glm::perspective(fovY, aspect, nearPlane, farPlane);
  v.eye = eye;
  return v;
}

float viewDistance(const glm::mat4& p, float depth01) {
  // clip.z = p22 z + p32, clip.w = -z  =>  z = p32 / (-ndc - p22), distance = -z.
  const float ndc = 2.0f * depth01 - 1.0f;
  return -p[3][2] / (-ndc - p[2][2]);
}

}  // namespace sandstorm
