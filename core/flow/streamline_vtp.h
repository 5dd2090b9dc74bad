// writeStreamlinesVtp: streamlines as VTK XML PolyData (.vtp) polylines that
// ParaView and VTK open: one line cell per streamline, point data "velocity"
// (vector, m/s), "speed" (m/s), "arc_length" (m from the seed, negative
// behind it) and, when the colour quantity is a velocity component, that
// component under its attribute name ("velocity_z"), and `extra` arrays (the
// colour quantity's: core/flow/polyline_color.h). Particles' trails are
// written the same way (app: --dump-trails), each a line ending at its
// particle, with the particle's velocity along it.
#pragma once

#include <filesystem>
#include <span>
#include <string>

#include "core/color/color_scale.h"
#include "core/flow/polyline_color.h"
#include "core/flow/streamline_tracer.h"

namespace sandstorm {

// Throws Error "`what` path: reason" when it cannot be written, or when an
// extra array has not one value a point.
void writeStreamlinesVtp(std::span<const Streamline> lines, ColorQuantity colorBy,
                         const std::filesystem::path& path,
                         const std::string& what = "--dump-streamlines",
                         std::span<const PointArray> extra = {});

}  // namespace sandstorm
