#include "contexts/platform/gl_context.h"

#include <epoxy/gl.h>

#include "contexts/gl/out_of_memory.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei,
                               const GLchar* message, const void*) {
  if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
  // A shader that fails to compile throws with its log (gl::Program); the
  // compiler's warnings (a library's shared GLSL, PNanoVDB.h, has many) are
  // for whoever debugs a shader.
  if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) {
    log::debug("GL (", id, "): ", message);
    return;
  }
  // A checked allocation says what ran out and which setting to lower.
  if (gl::outOfMemoryIsChecked(message)) {
    log::debug("GL (", id, "): ", message);
    return;
  }
  if (type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH)
    log::error("GL (", id, "): ", message);
  else if (severity == GL_DEBUG_SEVERITY_MEDIUM)
    log::warn("GL (", id, "): ", message);
  else
    log::debug("GL (", id, "): ", message);
}

}  // namespace

std::string glDescription() {
  const auto str = [](GLenum e) {
    const auto* s = reinterpret_cast<const char*>(glGetString(e));
    return std::string(s ? s : "?");
  };
  return "OpenGL " + str(GL_VERSION) + ", " + str(GL_RENDERER);
}

bool softwareRenderer(const std::string& description) {
  for (const char* name : {"llvmpipe", "softpipe", "SwiftShader"})
    if (description.find(name) != std::string::npos) return true;
  return false;
}

void checkGl45(const std::string& provider) {
  const int version = epoxy_gl_version();
  if (version < 45)
    throw Error(concat(provider, ": OpenGL 4.5 core is required, but the context offers ",
                       version / 10, ".", version % 10, " (", glDescription(),
                       "). Missing: OpenGL 4.5 (direct state access, transform feedback 3, ",
                       "geometry and compute shaders). Update the driver or use Mesa's llvmpipe."));
  GLint profile = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  if (!(profile & GL_CONTEXT_CORE_PROFILE_BIT))
    throw Error(concat(provider, ": expected a core profile context, got ", glDescription()));
  glEnable(GL_DEBUG_OUTPUT);
  glDebugMessageCallback(onDebugMessage, nullptr);
}

}  // namespace sandstorm
