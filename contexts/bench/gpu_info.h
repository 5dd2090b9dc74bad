// What sandstorm-bench reports about the GPU and the few GL calls it needs
// outside its stages (the app makes no GL calls of its own).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace sandstorm::bench {

std::string glRenderer();  // GL_VENDOR, GL_RENDERER, GL_VERSION
// Dedicated GPU memory where the driver tells (NVX_gpu_memory_info), in bytes.
std::optional<std::size_t> gpuMemoryBytes();
// Waits until the GPU has run every command issued so far.
void finishGpu();

}  // namespace sandstorm::bench
