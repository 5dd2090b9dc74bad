#include "contexts/bench/gpu_info.h"

#include <epoxy/gl.h>

#include "contexts/platform/gpu_memory.h"

namespace sandstorm::bench {

std::string glRenderer() {
  auto text = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "?");
  };
  return text(GL_VENDOR) + " | " + text(GL_RENDERER) + " | " + text(GL_VERSION);
}

std::optional<std::size_t> gpuMemoryBytes() {
  const std::optional<std::uint64_t> bytes = currentGpuMemory();
  if (!bytes) return std::nullopt;
  return std::size_t(*bytes);
}

void finishGpu() {
  glFinish();
}

}  // namespace sandstorm::bench
