// FieldPrimitive: one piece of a field composed in the field editor (thesis
// 7.2's "vector field creator/editor"): a vortex, a source or sink, a uniform
// wind, or one of the analytic fields of core/field, placed in the room (the
// particles' metres, z up, like the obstacles). The field the particles feel
// is the field in use plus every enabled primitive (core/editor/field_composer.h).
//
// Every primitive reads the same four numbers, each kind in its own way
// (PrimitiveField says exactly how):
//   kind         position          axis               strength (m/s)        radius (m)
//   vortex       a point on it     the line's axis    swirl at the radius   core (Lamb-Oseen)
//   source       the centre        -                  outward at the radius core; < 0: a sink
//   wind         -                 blows along it     speed                 -
//   tornado      the base          the funnel's axis  spin at the core      core
//   sphere_flow  the sphere        the stream's way   stream speed          the sphere's
//   curl_noise   shifts the eddies -                  typical speed         eddy size
// The state holds kMaxPrimitives of them always; kind none is an empty slot
// (the editor adds by filling one and removes by emptying it).
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

enum class PrimitiveKind : int {
  None = 0,
  Vortex = 1,
  Source = 2,
  Wind = 3,
  Tornado = 4,
  SphereFlow = 5,
  CurlNoise = 6
};

struct FieldPrimitive {
  PrimitiveKind kind = PrimitiveKind::None;
  glm::vec3 position{0.0f, 0.0f, 2.0f};  // m, room
  glm::vec3 axis{0.0f, 0.0f, 1.0f};      // a direction (its length does not matter)
  float strength = 2.0f;                 // m/s
  float radius = 1.0f;                   // m
  bool enabled = true;

  bool active() const { return kind != PrimitiveKind::None && enabled; }
  bool operator==(const FieldPrimitive&) const = default;
};

}  // namespace sandstorm
