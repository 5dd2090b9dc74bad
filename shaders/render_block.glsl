// How particles look: the twin of RenderBlock in contexts/render/frame_blocks.h.
layout(std140, binding = 2) uniform RenderBlock {
  vec4 colorBirth;      // rgb, a: opacity at birth
  vec4 colorDeath;      // rgb, a: opacity at death
  vec4 lightDirection;  // xyz towards the light (unit), w: ambient share
  vec4 params;          // x: size (m), y: softness (m), z: 1 for billboards, 0 for points
} look;
