#include "core/field/field_placement.h"

namespace sandstorm {

glm::mat4 FieldPlacement::matrix() const {
  glm::mat4 m(rotation * scale);
  m[3] = glm::vec4(offset, 1.0f);
  return m;
}

}  // namespace sandstorm
