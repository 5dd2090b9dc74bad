#include "contexts/ui/progress_window.h"

#include <epoxy/gl.h>

#include <GLFW/glfw3.h>

#include <algorithm>

namespace sandstorm {
namespace {

GlfwWindow::Options options() {
  GlfwWindow::Options o;
  o.title = "Sandstorm: loading";
  o.size = {640, 96};
  o.vsync = true;
  return o;
}

// Fills the pixels [x0, x1) x [y0, y1) with a colour.
void fill(int x0, int y0, int x1, int y1, float r, float g, float b) {
  if (x1 <= x0 || y1 <= y0) return;
  glScissor(x0, y0, x1 - x0, y1 - y0);
  glClearColor(r, g, b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

}  // namespace

ProgressWindow::ProgressWindow(const GlfwLibrary& glfw) : window_(glfw, options()) {}

void ProgressWindow::show(const std::optional<ProgressSnapshot>& work) {
  window_.makeCurrent();
  const glm::ivec2 size = window_.framebufferSize();
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0.08f, 0.09f, 0.11f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  // The bar: a frame, its inside, and the share done filled from the left.
  const int margin = std::max(8, size.y / 4), x0 = margin, x1 = size.x - margin;
  const int y0 = margin, y1 = size.y - margin;
  fill(x0 - 2, y0 - 2, x1 + 2, y1 + 2, 0.55f, 0.58f, 0.62f);
  fill(x0, y0, x1, y1, 0.14f, 0.15f, 0.18f);
  const double share = work ? work->fraction() : 0.0;
  fill(x0, y0, x0 + int(double(x1 - x0) * share + 0.5), y1, 0.90f, 0.62f, 0.22f);
  glDisable(GL_SCISSOR_TEST);
  window_.swapBuffers();
  window_.releaseCurrent();
  glfwSetWindowTitle(window_.handle(),
                     work ? ("Sandstorm: " + work->text()).c_str() : "Sandstorm: loading");
}

}  // namespace sandstorm
