#include "contexts/platform/glfw_window.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

void onGlfwError(int code, const char* message) {
  log::error("GLFW (", code, "): ", message);
}

}  // namespace

GlfwLibrary::GlfwLibrary() {
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit())
    throw Error(
        "GlfwLibrary: glfwInit failed; is there a display (DISPLAY or WAYLAND_DISPLAY)? "
        "Use an offscreen configuration to render without one.");
}

GlfwLibrary::~GlfwLibrary() {
  glfwTerminate();
}

int GlfwLibrary::monitorCount() const {
  int count = 0;
  glfwGetMonitors(&count);
  return count;
}

void GlfwLibrary::pollEvents() {
  glfwPollEvents();
}

GlfwWindow::GlfwWindow(const GlfwLibrary& glfw, const Options& o) {
  int monitorCount = 0;
  GLFWmonitor** monitors = glfwGetMonitors(&monitorCount);
  if (o.monitor < 0 || o.monitor >= std::max(monitorCount, 1))
    throw Error(concat("GlfwWindow '", o.title, "': monitor ", o.monitor, " does not exist (",
                       glfw.monitorCount(), " connected)"));
  GLFWmonitor* monitor = monitorCount > 0 ? monitors[o.monitor] : nullptr;

  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_DECORATED, o.decorated ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_VISIBLE, o.visible ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_STEREO, o.quadBufferStereo ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);

  glm::ivec2 size = o.size;
  if (o.fullscreen && monitor) {
    const GLFWvidmode* mode = glfwGetVideoMode(monitor);
    size = {mode->width, mode->height};
  }
  GLFWwindow* const before = glfwGetCurrentContext();  // current again afterwards
  window_ = glfwCreateWindow(size.x, size.y, o.title.c_str(), o.fullscreen ? monitor : nullptr,
                             o.share ? o.share->window_ : nullptr);
  if (!window_)
    throw Error(concat("GlfwWindow '", o.title, "': could not create a window with OpenGL 4.5 core",
                       o.quadBufferStereo ? " and quad-buffer stereo" : "",
                       ". Missing: a driver offering that context on this display"));
  if (!o.fullscreen && o.position.x >= 0 && o.position.y >= 0) {
    int mx = 0, my = 0;
    if (monitor) glfwGetMonitorPos(monitor, &mx, &my);
    glfwSetWindowPos(window_, mx + o.position.x, my + o.position.y);
  }
  makeCurrent();
  try {
    checkGl45("GlfwWindow '" + o.title + "'");
  } catch (...) {
    glfwDestroyWindow(window_);
    glfwMakeContextCurrent(before);
    throw;
  }
  glfwSwapInterval(o.vsync ? 1 : 0);
  description_ = "GLFW window '" + o.title + "': " + glDescription();
  glfwMakeContextCurrent(before);
}

GlfwWindow::~GlfwWindow() {
  if (window_) glfwDestroyWindow(window_);
}

void GlfwWindow::makeCurrent() {
  glfwMakeContextCurrent(window_);
}
void GlfwWindow::releaseCurrent() {
  glfwMakeContextCurrent(nullptr);
}
void GlfwWindow::swapBuffers() {
  glfwSwapBuffers(window_);
}

glm::ivec2 GlfwWindow::framebufferSize() const {
  glm::ivec2 s;
  glfwGetFramebufferSize(window_, &s.x, &s.y);
  return s;
}

bool GlfwWindow::shouldClose() const {
  return glfwWindowShouldClose(window_);
}
void GlfwWindow::requestClose() {
  glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

}  // namespace sandstorm
