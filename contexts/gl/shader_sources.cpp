#include "contexts/gl/shader_sources.h"

#include "core/util/error.h"

namespace sandstorm::gl {

std::string_view shaderSource(std::string_view name) {
  for (const ShaderSource& s : embeddedShaders())
    if (s.name == name) return s.text;
  throw Error(concat("shader file '", name, "' is not among the embedded shaders/ files"));
}

}  // namespace sandstorm::gl
