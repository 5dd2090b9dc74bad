// FieldPlacement: where a field sits in the room, as a similarity transform
//   room = offset + scale * rotation * local.
// Trajectories transform with the field: a field shrunk by `scale` also has its
// velocities scaled by `scale`, so particles trace the same (shrunk) paths in the
// same time. The identity placement is exact: it changes no bit of any sample.
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

struct FieldPlacement {
  glm::vec3 offset{0.0f};
  float scale = 1.0f;
  glm::mat3 rotation{1.0f};  // orthonormal

  glm::vec3 toLocal(const glm::vec3& room) const {
    return (glm::transpose(rotation) * (room - offset)) * (1.0f / scale);
  }
  glm::vec3 toRoom(const glm::vec3& local) const { return offset + (rotation * local) * scale; }
  // A field value (velocity or acceleration) carried from field to room.
  glm::vec3 vectorToRoom(const glm::vec3& v) const { return (rotation * v) * scale; }
  glm::vec3 vectorToLocal(const glm::vec3& v) const {
    return (glm::transpose(rotation) * v) * (1.0f / scale);
  }
  glm::mat4 matrix() const;  // local -> room, for drawing the field's box
};

}  // namespace sandstorm
