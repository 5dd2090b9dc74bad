#include "contexts/particles/scan_spin.h"

#include <epoxy/gl.h>

#include <cstring>

namespace sandstorm {

std::uint32_t scanSpinLimit(const GpuTuning& tuning) {
  if (tuning.scanSpin) return *tuning.scanSpin;
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const bool software =
      renderer && (std::strstr(renderer, "llvmpipe") || std::strstr(renderer, "softpipe"));
  return software ? 64u : 1u << 20;
}

}  // namespace sandstorm
