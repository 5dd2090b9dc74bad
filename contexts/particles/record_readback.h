// readRecords: the first `count` vec4 records of a GPU buffer, read through a
// staging copy. Reading a buffer from the CPU can make a driver move it to
// host memory for good (NVIDIA does, and its atomics then fail there), so the
// particle and control buffers are never read directly. Waits for the GPU.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace sandstorm {

std::vector<glm::vec4> readRecords(std::uint32_t buffer, std::size_t count);

}  // namespace sandstorm
