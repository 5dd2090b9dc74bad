// GpuTuning: how the GPU backends do their work, never what they compute:
// every choice draws the same particles (tests compare each with the CPU
// reference or with the other choice). [gpu] in a configuration
// (config/README.md); docs/PERFORMANCE.md measures them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

namespace sandstorm {

struct GpuTuning {
  enum class Splat { Tiled, Atomic };
  enum class FieldStorage { Auto, Texture };
  enum class TrailPass { Auto, Tiled, Atomic };

  // Splats: tiled (binned per screen tile, blended in order) or atomic (one
  // atomic add a pixel; the simpler variant, slower with many particles).
  Splat splat = Splat::Tiled;
  std::size_t splatChunk = 8192;  // records one splat workgroup takes from a tile list
  std::size_t splatList = 0;      // records the tile lists hold; 0: two a particle of capacity
  // How splat views add trails: tiled (runs of pixels binned per tile, like
  // the splats: faster where trails run long on screen), atomic (a global
  // atomic a pixel: faster where they are short), or Auto: time both as the
  // views are drawn and keep the faster (FasterChoice). Tiled needs the
  // tiled splats.
  TrailPass trailPass = TrailPass::Auto;
  // The compute backend keeps a field's grid in a storage buffer when it fits
  // (Auto) or always in a 3D texture, as the transform-feedback backend does.
  FieldStorage fieldStorage = FieldStorage::Auto;
  int updateItems = 4;  // records an invocation of the compute update advances: 1, 2, 4, 8
  // How often a tile of the compute update's scan reads a slow predecessor's
  // status before counting that tile's survivors itself; unset: NVIDIA's
  // GPUs wait without a limit (contexts/particles/scan_spin.h), 64 on a CPU
  // rasterizer (llvmpipe), 2^20 on other GPUs.
  std::optional<std::uint32_t> scanSpin;
  // A series' steps copied to the GPU by a second context of each drawing
  // context (UploadThread), beside the walls' work; false: by the walls' thread.
  bool uploadContext = true;
};

}  // namespace sandstorm
