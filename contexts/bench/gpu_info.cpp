#include "contexts/bench/gpu_info.h"

#include <epoxy/gl.h>

namespace sandstorm::bench {

std::string glRenderer() {
  auto text = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "?");
  };
  return text(GL_VENDOR) + " | " + text(GL_RENDERER) + " | " + text(GL_VERSION);
}

std::optional<std::size_t> gpuMemoryBytes() {
  if (!epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) return std::nullopt;
  GLint kib = 0;
  glGetIntegerv(GL_GPU_MEMORY_INFO_DEDICATED_VIDMEM_NVX, &kib);
  return std::size_t(kib) * 1024;
}

void finishGpu() {
  glFinish();
}

}  // namespace sandstorm::bench
