// How often a tile of an order-keeping compaction (shaders/tile_lookback.glsl)
// reads a predecessor's status before counting that tile's survivors itself.
// GPUs run the workgroups of a dispatch side by side, so a predecessor
// publishes soon; a CPU rasterizer may not (and llvmpipe caps a shader's loop
// iterations), so there the tile counts for itself at once. [gpu] scan_spin
// sets it (tests of both paths). Needs a GL context current.
#pragma once

#include <cstdint>

#include "core/config/gpu_tuning.h"

namespace sandstorm {

std::uint32_t scanSpinLimit(const GpuTuning& tuning);

}  // namespace sandstorm
