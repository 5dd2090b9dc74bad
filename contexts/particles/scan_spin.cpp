#include "contexts/particles/scan_spin.h"

#include <epoxy/gl.h>

#include <string_view>

#include "contexts/platform/gl_context.h"

namespace sandstorm {

ScanWait scanWait(const GpuTuning& tuning) {
  if (tuning.scanSpin) return {.waits = false, .spins = *tuning.scanSpin};
  if (softwareRenderer(glDescription())) return {.waits = false, .spins = 64u};
  const auto* vendor = reinterpret_cast<const char*>(glGetString(GL_VENDOR));
  if (vendor && std::string_view(vendor).find("NVIDIA") != std::string_view::npos)
    return {.waits = true, .spins = 0u};
  return {.waits = false, .spins = 1u << 20};
}

}  // namespace sandstorm
