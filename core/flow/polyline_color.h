// The colour-by quantity along the polylines --dump-streamlines and
// --dump-trails write (core/flow/streamline_vtp.h), as the walls colour them,
// so that ParaView colours the file by what the scientist saw: speed and the
// velocity components are the writer's own arrays; these add the vorticity, a
// file's scalar array (sampled from the colour grid, FieldUpdate::colorGrid)
// and, for trails, the particle's age.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/color/color_scale.h"
#include "core/flow/streamline_tracer.h"
#include "core/sim/frame_packet.h"
#include "core/sim/particle.h"

namespace sandstorm {

// One value a point of the lines, in the lines' order.
struct PointArray {
  std::string name;
  std::vector<float> values;
};

// What colours the lines: the quantity, and for vorticity and arrays the
// field's colour grid (null when the field has none), its blend towards the
// next frame and the factor the walls scale it by (shaders' colorGridAt).
struct LineColoring {
  ColorQuantity quantity = ColorQuantity::Age;
  const FieldUpdate* field = nullptr;
  float blend = 0.0f;
  float strength = 1.0f;  // sim.field_strength: vorticity is |strength| times the grid's
};

// The colour grid's value at `point` (the particles' coordinates): the GPU's
// colorGridAt on the CPU. 0 without a grid.
float colorGridAt(const LineColoring& c, const glm::vec3& point);

// The array a .vtp of streamlines needs besides velocity and speed: the
// vorticity or the file's array at each point (each point coloured by the
// field there, as streamline.vert does); none for the particle's own
// quantities (a streamline has no age) or without a grid.
std::optional<PointArray> streamlineColorArray(std::span<const Streamline> lines,
                                               const LineColoring& c);

// The same for trails, each drawn in its particle's colour: `particles[i]`'s
// value (its age, or the grid's value where it is) along all of trail i.
// `lines[i]` is particle `owners[i]`'s trail.
std::optional<PointArray> trailColorArray(std::span<const Streamline> lines,
                                          std::span<const std::size_t> owners,
                                          std::span<const Particle> particles,
                                          const LineColoring& c);

}  // namespace sandstorm
