// The shader files of shaders/, compiled into the binary at build time
// (cmake/EmbedShaders.cmake), looked up by file name.
#pragma once

#include <span>
#include <string_view>

namespace sandstorm::gl {

struct ShaderSource {
  std::string_view name;
  std::string_view text;
};

std::span<const ShaderSource> embeddedShaders();

// The text of shaders/<name>; throws Error naming the file when there is none.
std::string_view shaderSource(std::string_view name);

}  // namespace sandstorm::gl
