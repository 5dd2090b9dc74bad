// What the shadow map's receivers bind (OpacityShadowMap): its block, at
// uniform binding 4, and its map, at texture unit 7 (shaders/shadow_block.glsl).
#pragma once

#include <cstdint>

namespace sandstorm {

struct ShadowHandles {
  std::uint32_t block = 0, texture = 0;
  void bind() const;  // needs a GL context current
};

}  // namespace sandstorm
