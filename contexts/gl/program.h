// Program: a linked GLSL program built from files of shaders/.
//
// Each stage comes from one file (its stage from the extension: .vert .geom
// .frag .comp). Files may `#include "name.glsl"` other files of shaders/; each
// `defines` entry becomes a `#define` line after `#version`. Compile and link
// errors throw Error with the file's name, a map from GLSL source-string
// numbers to file names, and the driver's log.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "contexts/gl/objects.h"

namespace sandstorm::gl {

struct ProgramDesc {
  std::vector<std::string> files;
  std::vector<std::string> defines;           // "BILLBOARDS", "MAX_EMIT 64"
  std::vector<std::string> feedbackVaryings;  // captured into separate buffers, in order
};

class Program {
 public:
  explicit Program(const ProgramDesc& desc);
  explicit Program(std::vector<std::string> files, std::vector<std::string> defines = {})
      : Program(ProgramDesc{std::move(files), std::move(defines), {}}) {}

  void use() const;
  std::uint32_t id() const { return program_.id(); }
  // Location of a uniform, or -1 if the linker removed it. Cached.
  int uniform(std::string_view name) const;

 private:
  ProgramObject program_;
  std::string name_;
  mutable std::map<std::string, int, std::less<>> locations_;
};

// The source handed to the compiler: defines inserted, includes expanded with
// #line directives. Exposed for tests. `files` receives the name of each
// source-string number used in #line.
std::string preprocessShader(std::string_view fileName, const std::vector<std::string>& defines,
                             std::vector<std::string>& files);

}  // namespace sandstorm::gl
