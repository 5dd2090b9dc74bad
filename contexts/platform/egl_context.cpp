#include "contexts/platform/egl_context.h"

#include <epoxy/egl.h>

#include <mutex>
#include <string>
#include <vector>

#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

struct Display {
  EGLDisplay display = EGL_NO_DISPLAY;
  std::string platform;
};

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const std::string all = std::string(" ") + list + " ";
  return all.find(std::string(" ") + name + " ") != std::string::npos;
}

// Every device offering desktop OpenGL with surfaceless contexts, in EGL's order.
std::vector<Display> tryDevicePlatform(const char* clientExtensions) {
  // NVIDIA's libEGL names enumeration and query together as EGL_EXT_device_base.
  if (!hasExtension(clientExtensions, "EGL_EXT_platform_device") ||
      !(hasExtension(clientExtensions, "EGL_EXT_device_enumeration") ||
        hasExtension(clientExtensions, "EGL_EXT_device_base")))
    return {};
  EGLint count = 0;
  eglQueryDevicesEXT(0, nullptr, &count);
  std::vector<EGLDeviceEXT> devices(std::size_t(std::max(count, 0)));
  eglQueryDevicesEXT(count, devices.data(), &count);
  std::vector<Display> usable;
  for (EGLint i = 0; i < count; ++i) {
    EGLDisplay d =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[std::size_t(i)], nullptr);
    EGLint major = 0, minor = 0;
    if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) {
      const char* ext = eglQueryString(d, EGL_EXTENSIONS);
      if (hasExtension(ext, "EGL_KHR_surfaceless_context") && eglBindAPI(EGL_OPENGL_API)) {
        usable.push_back({d, concat("EGL device platform, device ", usable.size())});
        continue;
      }
      eglTerminate(d);
    }
  }
  return usable;
}

Display trySurfaceless(const char* clientExtensions) {
  if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) return {};
  EGLDisplay d =
      eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (d == EGL_NO_DISPLAY || !eglInitialize(d, &major, &minor)) return {};
  return {d, "EGL Mesa surfaceless platform"};
}

// The displays, found once per process: a display per GPU on the EGL device
// platform, else Mesa's surfaceless platform (one display: llvmpipe).
const std::vector<Display>& displays() {
  static std::once_flag once;
  static std::vector<Display> chosen;
  static std::string failure;
  std::call_once(once, [] {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    chosen = tryDevicePlatform(client);
    if (chosen.empty())
      if (Display d = trySurfaceless(client); d.display != EGL_NO_DISPLAY) chosen.push_back(d);
    if (chosen.empty())
      failure = concat("EglContext: no usable EGL display. Tried EGL_EXT_platform_device and ",
                       "EGL_MESA_platform_surfaceless; client extensions: ",
                       client ? client : "(none: is libEGL installed?)");
  });
  if (chosen.empty()) throw Error(failure);
  return chosen;
}

}  // namespace

int EglContext::deviceCount() {
  return int(displays().size());
}

EglContext::EglContext(const Options& options) : device_(options.device) {
  const std::vector<Display>& all = displays();
  if (options.device < 0 || options.device >= int(all.size()))
    throw Error(concat("GPU ", options.device, " does not exist: OpenGL can use ", all.size(),
                       " GPU(s) here through the ",
                       all.front().platform.substr(0, all.front().platform.find(',')),
                       "; expected gpu 0..", all.size() - 1));
  if (options.share && options.share->device_ != options.device)
    throw Error("EglContext: contexts on different GPUs cannot share objects");
  const Display& d = all[std::size_t(options.device)];
  display_ = d.display;
  if (!eglBindAPI(EGL_OPENGL_API)) throw Error("EglContext: eglBindAPI(EGL_OPENGL_API) failed");

  const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  const bool noConfig =
      hasExtension(eglQueryString(d.display, EGL_EXTENSIONS), "EGL_KHR_no_config_context");
  if (!eglChooseConfig(d.display, configAttribs, &config, 1, &configs) || configs == 0) {
    if (!noConfig)
      throw Error(concat("EglContext: no EGL config with desktop OpenGL on ", d.platform));
    config = EGL_NO_CONFIG_KHR;
  }
  const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                   4,
                                   EGL_CONTEXT_MINOR_VERSION,
                                   5,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                   EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                   EGL_CONTEXT_OPENGL_DEBUG,
                                   options.debug ? EGL_TRUE : EGL_FALSE,
                                   EGL_NONE};
  EGLContext share =
      options.share ? static_cast<EGLContext>(options.share->context_) : EGL_NO_CONTEXT;
  // The thread's current context, if any, is current again afterwards.
  const struct Current {
    EGLDisplay display = eglGetCurrentDisplay();
    EGLSurface draw = eglGetCurrentSurface(EGL_DRAW), read = eglGetCurrentSurface(EGL_READ);
    EGLContext context = eglGetCurrentContext();
    void restore() const {
      if (context != EGL_NO_CONTEXT) eglMakeCurrent(display, draw, read, context);
    }
  } before;
  context_ = eglCreateContext(d.display, config, share, contextAttribs);
  if (context_ == EGL_NO_CONTEXT)
    throw Error(concat("EglContext: eglCreateContext for OpenGL 4.5 core failed on ", d.platform,
                       " (EGL error 0x", std::hex, eglGetError(),
                       "). Missing: an OpenGL 4.5 core profile driver"));
  makeCurrent();
  try {
    checkGl45("EglContext (" + d.platform + ")");
  } catch (...) {
    releaseCurrent();
    eglDestroyContext(d.display, context_);
    before.restore();
    throw;
  }
  description_ = d.platform + ": " + glDescription();
  releaseCurrent();  // the thread that renders makes it current
  before.restore();
}

EglContext::~EglContext() {
  if (eglGetCurrentContext() == context_) releaseCurrent();
  eglDestroyContext(display_, context_);
}

void EglContext::makeCurrent() {
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
    throw Error(
        concat("EglContext: eglMakeCurrent failed (EGL error 0x", std::hex, eglGetError(), ")"));
}

void EglContext::releaseCurrent() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

}  // namespace sandstorm
