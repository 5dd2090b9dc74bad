// GlContext: an OpenGL 4.5 core context from some provider (EGL offscreen or a
// GLFW window). A context is current on at most one thread at a time; its
// owner makes it current on the thread that renders with it.
#pragma once

#include <string>

#include <glm/glm.hpp>

namespace sandstorm {

class GlContext {
 public:
  virtual ~GlContext() = default;

  virtual void makeCurrent() = 0;
  virtual void releaseCurrent() = 0;
  // Presents the default framebuffer; offscreen contexts have none and do nothing.
  virtual void swapBuffers() = 0;
  // Size of the default framebuffer in pixels; (0, 0) for offscreen contexts.
  virtual glm::ivec2 framebufferSize() const = 0;
  // "EGL (device platform, NVIDIA ...): OpenGL 4.6 ..." for logs and reports.
  virtual std::string description() const = 0;
};

// Checks the current context: OpenGL >= 4.5 core. Throws Error naming the
// context, the version found and what is missing. Installs GL debug output
// (KHR_debug) that forwards driver errors and warnings to the log.
void checkGl45(const std::string& provider);

// "OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits)".
std::string glDescription();
// Whether a description (glDescription) names a software renderer (Mesa's
// llvmpipe or softpipe, SwiftShader).
bool softwareRenderer(const std::string& description);

}  // namespace sandstorm
