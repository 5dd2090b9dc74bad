#include "contexts/platform/gpu_memory.h"

#include <algorithm>
#include <mutex>

#include <epoxy/gl.h>

#include "contexts/platform/egl_context.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

std::mutex mutex;
std::optional<std::optional<std::uint64_t>> answer;  // asked already: the answer

std::optional<std::uint64_t> ask() {
  try {
    std::optional<std::uint64_t> smallest;
    for (int device = 0; device < EglContext::deviceCount(); ++device) {
      EglContext context(EglContext::Options{.device = device});
      context.makeCurrent();
      const std::optional<std::uint64_t> bytes = currentGpuMemory();
      context.releaseCurrent();
      if (!bytes) return std::nullopt;  // a GPU that does not tell: no answer
      smallest = smallest ? std::min(*smallest, *bytes) : *bytes;
    }
    return smallest;
  } catch (const std::exception& e) {
    log::debug("GPU memory: no answer (", e.what(), ")");
    return std::nullopt;
  }
}

}  // namespace

std::optional<std::uint64_t> currentGpuMemory() {
  if (!epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) return std::nullopt;
  GLint kib = 0;
  glGetIntegerv(GL_GPU_MEMORY_INFO_DEDICATED_VIDMEM_NVX, &kib);
  if (kib <= 0) return std::nullopt;
  return std::uint64_t(kib) * 1024;
}

std::optional<std::uint64_t> smallestGpuMemory() {
  std::lock_guard lock(mutex);
  if (!answer) answer = ask();
  return *answer;
}

void pretendGpuMemory(std::uint64_t bytes) {
  std::lock_guard lock(mutex);
  answer = std::optional<std::uint64_t>(bytes);
}

}  // namespace sandstorm
