// How a tile of an order-keeping compaction (shaders/tile_lookback.glsl)
// waits for a predecessor that has not published its count yet.
//   NVIDIA's GPUs run a dispatch's started workgroups side by side, so a
//     predecessor (which took its ticket earlier, so is running) always
//     publishes: the tile waits for it, and the program has no recount
//     (LOOKBACK_WAITS), so it holds the physics once, not twice (the H200's
//     update 1.055x faster at 10^8: docs/PERFORMANCE.md).
//   Elsewhere the tile reads the status `spins` times, then counts that
//     tile's survivors itself: after 64 reads on a CPU rasterizer (llvmpipe, which
//     need not run workgroups together and caps a shader's loop iterations),
//     after 2^20 reads on other GPUs, whose scheduling is not known here.
// [gpu] scan_spin sets the reads (and so the recount: tests of both paths).
// Needs a GL context current.
#pragma once

#include <cstdint>

#include "core/config/gpu_tuning.h"

namespace sandstorm {

struct ScanWait {
  bool waits = false;        // until the predecessor publishes (LOOKBACK_WAITS)
  std::uint32_t spins = 64;  // otherwise: reads before recounting (uSpinLimit)

  // The update programs' define, or null.
  const char* define() const { return waits ? "LOOKBACK_WAITS" : nullptr; }
};

ScanWait scanWait(const GpuTuning& tuning);

}  // namespace sandstorm
