#include "core/light/puff_sprite.h"

#include <algorithm>
#include <cmath>

namespace sandstorm {

std::vector<std::uint8_t> puffSpritePixels() {
  std::vector<std::uint8_t> pixels(kPuffSize * kPuffSize);
  for (int y = 0; y < kPuffSize; ++y)
    for (int x = 0; x < kPuffSize; ++x) {
      const float u = (x + 0.5f) / kPuffSize * 2.0f - 1.0f,
                  v = (y + 0.5f) / kPuffSize * 2.0f - 1.0f;
      const float r = std::sqrt(u * u + v * v);
      const float falloff = r >= 1.0f ? 0.0f : (1.0f - r * r) * (1.0f - r * r);
      const float lumps =
          0.8f + 0.2f * std::sin(9.0f * u + 3.0f * std::sin(7.0f * v)) * std::cos(8.0f * v);
      pixels[std::size_t(y * kPuffSize + x)] =
          std::uint8_t(std::clamp(falloff * lumps, 0.0f, 1.0f) * 255.0f + 0.5f);
    }
  return pixels;
}

float puffCoverage() {
  static const float coverage = [] {
    const std::vector<std::uint8_t> pixels = puffSpritePixels();
    double sum = 0.0;
    int inside = 0;
    for (int y = 0; y < kPuffSize; ++y)
      for (int x = 0; x < kPuffSize; ++x) {
        const float u = (x + 0.5f) / kPuffSize * 2.0f - 1.0f,
                    v = (y + 0.5f) / kPuffSize * 2.0f - 1.0f;
        if (u * u + v * v > 1.0f) continue;
        sum += pixels[std::size_t(y * kPuffSize + x)] / 255.0;
        ++inside;
      }
    return float(sum / inside);
  }();
  return coverage;
}

}  // namespace sandstorm
