#include "contexts/ui/progress_window.h"

#include <GLFW/glfw3.h>

#include <algorithm>

#include "contexts/ui/progress_bar.h"

namespace sandstorm {
namespace {

GlfwWindow::Options options() {
  GlfwWindow::Options o;
  o.title = "Sandstorm: loading";
  o.size = {640, 96};
  o.vsync = true;
  return o;
}

}  // namespace

ProgressWindow::ProgressWindow(const GlfwLibrary& glfw) : window_(glfw, options()) {}

void ProgressWindow::show(const std::optional<ProgressSnapshot>& work) {
  window_.makeCurrent();
  const glm::ivec2 size = window_.framebufferSize();
  const int margin = std::max(8, size.y / 4);
  drawProgressBar(glm::ivec4(0, 0, size.x, size.y),
                  glm::ivec4(margin, margin, size.x - 2 * margin, size.y - 2 * margin),
                  work ? work->fraction() : 0.0);
  window_.swapBuffers();
  window_.releaseCurrent();
  glfwSetWindowTitle(window_.handle(),
                     work ? ("Sandstorm: " + work->text()).c_str() : "Sandstorm: loading");
}

}  // namespace sandstorm
