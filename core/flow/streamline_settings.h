// StreamlineSettings: the seed rake of the streamlines every wall draws (the
// attributes streamlines.*): seeds on a line from `from` to `to`, or on a
// plane spanned by from->to and from->across, traced both ways through the
// current field.
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

enum class RakeShape : int { Line = 0, Plane = 1 };

struct StreamlineSettings {
  bool enabled = false;
  RakeShape shape = RakeShape::Line;
  glm::vec3 from{-4.0f, 0.0f, 2.0f};  // m, where the particles are (FieldPlacement's "room")
  glm::vec3 to{4.0f, 0.0f, 2.0f};
  glm::vec3 across{-4.0f, 0.0f, 6.0f};  // the plane's second edge ends here
  int seeds = 16;                       // along each edge (a plane has seeds x seeds)
  float step = 0.05f;                   // m of arc per integration step
  float length = 30.0f;                 // m: each direction stops here at the latest
  float width = 0.03f;                  // m: ribbon width (0: one-pixel lines)
};

}  // namespace sandstorm
