// traceStreamlines: streamlines of the field the particles feel (strength,
// placement and a time-varying field's blend included: fieldAt in
// core/sim/particle_physics.h), from each seed of the rake, both ways. The
// path is integrated in arc length, dx/ds = f / |f|, with the streamlines' own
// integrator (streamlines.integrator): Euler, RK2 or RK4 with a fixed step of
// `step` metres, or, by default, adaptive RK45 (Cash-Karp, as ParaView's
// Stream Tracer) whose steps, at most `step` and at least step / 64, halve
// while the fourth- and fifth-order solutions differ by more than
// `tolerance` metres or the step turns the line by more than about 29
// degrees, and double while they differ by under tolerance / 32
// (and halve where a step would leave the field or meet still air, so a line
// ends within step / 64 of the edge). Each direction stops where it leaves
// the field (or its valid cells), where
// the flow stands still (|f| < 1e-6 m/s), after `length` metres, or after
// streamlineSteps() points.
//
// The GPU twin is shaders/streamline_trace.comp (contexts/scene/streamline_renderer):
// the same operations on the same samples; step sizes change by halving and
// doubling and errors are compared squared, so an IEEE GPU takes the same
// steps.
#pragma once

#include <vector>

#include "core/flow/streamline_settings.h"
#include "core/sim/particle_physics.h"

namespace sandstorm {

struct StreamlinePoint {
  glm::vec3 position;  // room
  glm::vec3 velocity;  // the field there (m/s)
};

// One seed's line, from its backward end through the seed to its forward end.
struct Streamline {
  std::vector<StreamlinePoint> points;
  int seedIndex = 0;  // where the seed is in `points`
};

inline constexpr int kMaxStreamlineSteps = 4096;  // per direction
inline constexpr int kMaxStreamlineSeeds = 64;    // per rake edge
// Points of all lines together (the GPU's buffer: 32 bytes a point, 128 MiB).
inline constexpr int kMaxStreamlinePoints = 1 << 22;

// The rake's seeds: `seeds` along the line (ends included), or seeds x seeds
// on the plane. Seeds are clamped to 1..kMaxStreamlineSeeds.
std::vector<glm::vec3> rakeSeeds(const StreamlineSettings& rake);

// Points one direction may have: round(length / step) (16 times that for
// RK45), at most kMaxStreamlineSteps and fewer where the rake's lines would
// pass kMaxStreamlinePoints together.
int streamlineSteps(const StreamlineSettings& rake);

// `in`: the field, placement, blend and strength (its integrator, motion and
// dt are the particles' and are ignored).
std::vector<Streamline> traceStreamlines(const StreamlineSettings& rake, const PhysicsInputs& in);

}  // namespace sandstorm
