// The view's uniform block: the twin of ViewBlock in contexts/render/frame_blocks.h.
layout(std140, binding = 1) uniform ViewBlock {
  mat4 viewMatrix;
  mat4 projection;
  mat4 viewProjection;
  mat4 inverseViewProjection;
  vec4 eye;       // xyz: the eye in room metres
  vec4 viewport;  // x, y, width, height in pixels of this view's image
} view;

// Camera-space distance of a depth-buffer value (core/cave/view.h's viewDistance).
float viewDistance(float depth01) {
  float ndc = 2.0 * depth01 - 1.0;
  return -view.projection[3][2] / (-ndc - view.projection[2][2]);
}
