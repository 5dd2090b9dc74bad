// GpuMemory: how much memory the GPUs the walls may use have, asked of the
// driver before any wall opens (the main context decides the field's
// precision before the walls get it, so every wall and rank agrees): a
// short-lived EGL context on each GPU, NVX_gpu_memory_info's dedicated
// memory. No answer where the driver does not tell (Mesa's llvmpipe) or EGL
// fails. Asked once a process; asking again gives the first answer.
#pragma once

#include <cstdint>
#include <optional>

namespace sandstorm {

// The current context's GPU's dedicated memory, in bytes (NVX_gpu_memory_info).
std::optional<std::uint64_t> currentGpuMemory();

// The smallest dedicated memory among the GPUs, in bytes.
std::optional<std::uint64_t> smallestGpuMemory();

// For the tests (the hidden --debug-gpu-memory): answer this instead of asking.
void pretendGpuMemory(std::uint64_t bytes);

}  // namespace sandstorm
