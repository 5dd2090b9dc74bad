#include "contexts/particles/scan_spin.h"

#include "contexts/platform/gl_context.h"

namespace sandstorm {

std::uint32_t scanSpinLimit(const GpuTuning& tuning) {
  if (tuning.scanSpin) return *tuning.scanSpin;
  return softwareRenderer(glDescription()) ? 64u : 1u << 20;
}

}  // namespace sandstorm
