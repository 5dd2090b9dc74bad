// SliceSettings: the slice plane through the field (the attributes slice.*),
// coloured by the field's render.color_by quantity through render.color_map;
// ProbeSettings: the probe (probe.*).
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

struct SliceSettings {
  bool enabled = false;
  glm::vec3 origin{0.0f, 0.0f, 2.0f};  // a point of the plane (the particles' coordinates)
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // its normal (any length but 0)
  float opacity = 1.0f;
  int arrows = 0;  // arrow glyphs along the slice's longer side (0: none; core/flow/slice_arrows.h)
};

// The probe (core/flow/probe.h): the point where the flow is read.
struct ProbeSettings {
  bool enabled = false;
  glm::vec3 position{0.0f, 0.0f, 2.0f};  // without a tracked wand (the particles' coordinates)
  float radius = 0.25f;                  // m: particles this near are counted
  float reach = 1.0f;                    // m (room) along the wand's ray, without a slice
};

}  // namespace sandstorm
