// EglContext: an offscreen OpenGL 4.5 core context through EGL, with no window
// and no display server. It has no default framebuffer: draw into FBOs.
//
// The displays are found once per process: one per GPU on the EGL device
// platform (EGL_EXT_platform_device: NVIDIA and other GPU drivers), else
// Mesa's surfaceless platform (llvmpipe on machines without a GPU: one
// "GPU"). A context is made on the GPU Options::device names (0: the first).
// Contexts may share objects with another EglContext of the same GPU. A new
// context is not current on any thread; the thread that makes it keeps the
// context it had current.
#pragma once

#include <memory>

#include "contexts/platform/gl_context.h"

namespace sandstorm {

class EglContext final : public GlContext {
 public:
  struct Options {
    const EglContext* share = nullptr;
    bool debug = false;
    int device = 0;  // the GPU: an index into the usable EGL devices
  };

  // The GPUs contexts can be made on (at least 1, or the constructor throws).
  static int deviceCount();

  explicit EglContext(const Options& options);
  EglContext() : EglContext(Options{}) {}
  ~EglContext() override;
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  void makeCurrent() override;
  void releaseCurrent() override;
  void swapBuffers() override {}
  glm::ivec2 framebufferSize() const override { return {0, 0}; }
  std::string description() const override { return description_; }

 private:
  int device_ = 0;
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  std::string description_;
};

}  // namespace sandstorm
