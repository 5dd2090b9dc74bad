// writeStreamlinesVtp: streamlines as VTK XML PolyData (.vtp) polylines that
// ParaView and VTK open: one line cell per streamline, point data "velocity"
// (vector, m/s), "speed" (m/s), "arc_length" (m from the seed, negative
// behind it) and, when the colour quantity is a velocity component, that
// component under its attribute name ("velocity_z").
#pragma once

#include <filesystem>
#include <span>

#include "core/color/color_scale.h"
#include "core/flow/streamline_tracer.h"

namespace sandstorm {

// Throws Error "--dump-streamlines path: reason" when it cannot be written.
void writeStreamlinesVtp(std::span<const Streamline> lines, ColorQuantity colorBy,
                         const std::filesystem::path& path);

}  // namespace sandstorm
