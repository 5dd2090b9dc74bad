// Image: 8-bit RGBA pixels, top row first, and PNG output.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

namespace sandstorm {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, top row first

  glm::u8vec4 at(int x, int y) const {
    const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
  }
};

// Writes a PNG; throws Error naming the path when it cannot.
void writePng(const Image& image, const std::filesystem::path& path);
// Reads a PNG as RGBA; throws Error naming the path when it cannot.
Image readPng(const std::filesystem::path& path);

}  // namespace sandstorm
