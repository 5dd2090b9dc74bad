// GlfwWindow: a window with an OpenGL 4.5 core context, through GLFW.
//
// GLFW requires windows to be created, destroyed and polled on the main
// thread; the context may be made current and swapped on any one thread at a
// time (a wall's render thread). GlfwLibrary initialises GLFW for the life of
// the windows and must outlive them.
#pragma once

#include <string>

#include "contexts/platform/gl_context.h"

struct GLFWwindow;

namespace sandstorm {

class GlfwLibrary {
 public:
  GlfwLibrary();  // throws Error when there is no display
  ~GlfwLibrary();
  GlfwLibrary(const GlfwLibrary&) = delete;
  GlfwLibrary& operator=(const GlfwLibrary&) = delete;

  int monitorCount() const;
  static void pollEvents();
};

class GlfwWindow final : public GlContext {
 public:
  struct Options {
    std::string title = "Sandstorm";
    glm::ivec2 size{1280, 720};
    glm::ivec2 position{-1, -1};  // -1: let the window manager place it
    int monitor = 0;              // which monitor `position` is relative to, and fullscreen uses
    bool fullscreen = false;
    bool decorated = true;
    bool visible = true;
    bool quadBufferStereo = false;
    bool vsync = true;
    const GlfwWindow* share = nullptr;
  };

  GlfwWindow(const GlfwLibrary& glfw, const Options& options);
  ~GlfwWindow() override;
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  void makeCurrent() override;
  void releaseCurrent() override;
  void swapBuffers() override;
  glm::ivec2 framebufferSize() const override;
  std::string description() const override { return description_; }

  bool shouldClose() const;
  void requestClose();
  GLFWwindow* handle() const { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
  std::string description_;
};

}  // namespace sandstorm
