// Writes particles as VTK XML PolyData (.vtp), which ParaView and VTK open:
// points with "velocity" (vector), "age" and "life_remaining" (s) point data,
// and one vertex cell per particle so they show as points.
#pragma once

#include <filesystem>
#include <span>

#include "core/sim/particle.h"

namespace sandstorm {

// Throws Error naming the path when it cannot be written.
void writeParticlesVtp(std::span<const Particle> particles, const std::filesystem::path& path);

}  // namespace sandstorm
