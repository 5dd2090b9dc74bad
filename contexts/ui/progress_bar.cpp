#include "contexts/ui/progress_bar.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace sandstorm {
namespace {

// Fills the pixels [x0, x1) x [y0, y1) with a colour.
void fill(int x0, int y0, int x1, int y1, float r, float g, float b) {
  if (x1 <= x0 || y1 <= y0) return;
  glScissor(x0, y0, x1 - x0, y1 - y0);
  glClearColor(r, g, b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

}  // namespace

void drawProgressBar(glm::ivec4 viewport, glm::ivec4 bar, double share) {
  const glm::ivec4 v = viewport;
  glEnable(GL_SCISSOR_TEST);
  fill(v.x, v.y, v.x + v.z, v.y + v.w, 0.08f, 0.09f, 0.11f);
  // A frame, the bar's inside, and the share done filled from the left.
  const int x0 = bar.x, y0 = bar.y, x1 = bar.x + bar.z, y1 = bar.y + bar.w;
  fill(x0 - 2, y0 - 2, x1 + 2, y1 + 2, 0.55f, 0.58f, 0.62f);
  fill(x0, y0, x1, y1, 0.14f, 0.15f, 0.18f);
  const double done = std::clamp(share, 0.0, 1.0);
  fill(x0, y0, x0 + int(double(x1 - x0) * done + 0.5), y1, 0.90f, 0.62f, 0.22f);
  glDisable(GL_SCISSOR_TEST);
}

glm::ivec4 centredBar(glm::ivec4 viewport, float width) {
  const int w = std::max(1, int(float(viewport.z) * std::clamp(width, 0.0f, 1.0f)));
  const int h = std::max(6, viewport.w / 40);
  return {viewport.x + (viewport.z - w) / 2, viewport.y + (viewport.w - h) / 2, w, h};
}

}  // namespace sandstorm
